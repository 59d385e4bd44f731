# The rasterizer's coverage rule is a header shared with the shaders (passes/raytrace/raster_coverage.h).
target_include_directories(${exe} PRIVATE ${CMAKE_SOURCE_DIR}/passes ${CMAKE_SOURCE_DIR}/engine)
