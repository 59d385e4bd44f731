# Compare metrics, contact sheet and bench report: pure logic (no Vulkan, GLFW or ImGui).
target_link_libraries(${exe} PRIVATE ppr_metrics ppr_bench_report)
