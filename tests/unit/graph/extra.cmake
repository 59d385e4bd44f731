# The render graph core (no device: compile() plans barriers as plain data).
target_link_libraries(${exe} PRIVATE ppr_graph)
