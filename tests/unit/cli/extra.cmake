# The command-line parser and camera resolution (ppr_cli links the technique table, so Vulkan, but
# needs no device).
target_link_libraries(${exe} PRIVATE ppr_cli)
