# Compiles GLSL to SPIR-V at build time and embeds it as a uint32_t array header
# (glslangValidator --vn), so the executable needs no shader files at run time.
# ppr_add_shaders(TARGET target SHADERS a.comp b.frag ...): the header for passes/x/y.comp is
# <build>/shaders/y_comp.h with the array `y_comp`.
set(PPR_SHADER_OUT_DIR ${CMAKE_BINARY_DIR}/shaders)
file(MAKE_DIRECTORY ${PPR_SHADER_OUT_DIR})

function(ppr_add_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SHADERS" ${ARGN})
  set(headers)
  foreach(src ${ARG_SHADERS})
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    string(REPLACE "." "_" var ${name})
    set(out ${PPR_SHADER_OUT_DIR}/${var}.h)
    add_custom_command(
      OUTPUT ${out}
      COMMAND Vulkan::glslangValidator --target-env vulkan1.3 -V --quiet
              -I${CMAKE_SOURCE_DIR}/passes -I${CMAKE_SOURCE_DIR}/engine
              --depfile ${out}.d --vn ${var} -o ${out} ${abs}
      DEPENDS ${abs}
      DEPFILE ${out}.d
      COMMENT "GLSL ${name}"
      VERBATIM)
    list(APPEND headers ${out})
  endforeach()
  target_sources(${ARG_TARGET} PRIVATE ${headers})
  target_include_directories(${ARG_TARGET} PRIVATE ${PPR_SHADER_OUT_DIR})
endfunction()
