# The PPR encoding is a header shared with the shaders (passes/ppr_common/encoding.h).
target_include_directories(${exe} PRIVATE ${CMAKE_SOURCE_DIR}/passes)
