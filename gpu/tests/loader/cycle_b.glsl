// Loader fixture: the other half of an include cycle.
float cycleB() { return 1.0; }
#include "cycle_a.glsl"  // CYCLE
