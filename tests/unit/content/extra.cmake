# The content tests run the generator binary, so it must be built first.
add_dependencies(${exe} ppr_make_default_scene)
