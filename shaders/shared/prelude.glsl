// GLSL prelude for the dual-compiled headers in shaders/shared/ (see shared_cpp.h, its C++ twin).
#define PRISM_INLINE
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#define PRISM_PRECISE precise
#define PRISM_UNUSED(x)
#include "constants.glsl"
