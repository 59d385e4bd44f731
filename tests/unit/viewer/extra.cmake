# The viewer's pure pieces (timing history); ppr_viewer links GLFW, ImGui and Vulkan but the tests
# open no window and need no device.
target_link_libraries(${exe} PRIVATE ppr_viewer)
