# animation_test checks the default scene generated at build time, so it must be generated first.
add_dependencies(${exe} ppr_default_scene)
target_compile_definitions(${exe} PRIVATE PPR_DEFAULT_SCENE_FILE="${PPR_DEFAULT_SCENE}")
