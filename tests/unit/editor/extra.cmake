# The reflector editor's document model: pure logic (no Vulkan, GLFW or ImGui).
target_link_libraries(${exe} PRIVATE ppr_editor_model)
