# The technique table and its cost attribution (links the modules, so Vulkan, but needs no device).
target_link_libraries(${exe} PRIVATE ppr_techniques)
