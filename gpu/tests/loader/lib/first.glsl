// Loader fixture: resolves "second.glsl" beside itself, in lib/.
#include "second.glsl"

PRISM_INLINE uint first() { return 1u + second(); }
