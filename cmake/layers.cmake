# The layers of src/, lowest first, and the layers each may include and link (its arrows).
# One list, read by CMakeLists.txt (one library target per layer, linking exactly these)
# and by cmake/check_layers.cmake (every #include "layer/..." of a file must name its own
# layer or one listed here). docs/architecture.md draws the picture.
set(SWINGSIM_LAYERS core numerics knee model io leg swing sweep identify report study serve cli)
set(SWINGSIM_DEPS_core "")
set(SWINGSIM_DEPS_numerics core)
set(SWINGSIM_DEPS_knee core numerics)
set(SWINGSIM_DEPS_model core numerics knee)
set(SWINGSIM_DEPS_io core numerics knee model)
set(SWINGSIM_DEPS_leg core numerics knee model)
set(SWINGSIM_DEPS_swing core numerics knee model leg)
set(SWINGSIM_DEPS_sweep core numerics knee model leg swing)
set(SWINGSIM_DEPS_identify core numerics knee model leg swing sweep)
set(SWINGSIM_DEPS_report core numerics knee model io leg swing sweep identify)
set(SWINGSIM_DEPS_study core numerics knee model io leg swing sweep identify report)
set(SWINGSIM_DEPS_serve core numerics knee model io leg swing sweep identify report study)
set(SWINGSIM_DEPS_cli core numerics model io report study serve)
