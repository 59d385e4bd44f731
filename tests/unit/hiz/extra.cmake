# The hierarchy's layout is a header shared with the shaders (passes/hiz/hiz.h).
target_include_directories(${exe} PRIVATE ${CMAKE_SOURCE_DIR}/passes)
