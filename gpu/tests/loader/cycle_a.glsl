// Loader fixture: half of an include cycle.
#include "cycle_b.glsl"
