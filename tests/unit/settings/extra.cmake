# Declared settings and debug views: pure logic (ppr_settings links no Vulkan, GLFW or ImGui).
target_link_libraries(${exe} PRIVATE ppr_settings)
