# The PPR encoding is a header shared with the shaders (passes/ppr_common/encoding.h).
target_include_directories(${exe} PRIVATE ${CMAKE_SOURCE_DIR}/passes)
# tile_culling_test.cpp tests ReflectorBuffer::cullPlanes (passes/common/reflector_buffer.cpp).
target_link_libraries(${exe} PRIVATE ppr_passes)
