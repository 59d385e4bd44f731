# The compare metrics and contact sheet live in ppr_app (with the rest of `ppr compare`).
target_link_libraries(${exe} PRIVATE ppr_app)
