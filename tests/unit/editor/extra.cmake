# The reflector editor's document model lives in ppr_app (next to the viewer UI that drives it).
target_link_libraries(${exe} PRIVATE ppr_app)
