# The reflection tests read the project's real shaders: the SPIR-V headers ppr_passes generates.
target_link_libraries(${exe} PRIVATE ppr_shader)
target_include_directories(${exe} PRIVATE ${PPR_SHADER_OUT_DIR} ${CMAKE_SOURCE_DIR}/passes)
add_dependencies(${exe} ppr_passes)
