// Loader fixture: included twice (by lib/first.glsl and by main.comp), hence the guard.
#ifndef LOADER_SECOND_GLSL
#define LOADER_SECOND_GLSL
PRISM_INLINE uint second() { return 40u; }
#define SECOND_TWICE (2u * second())
#endif
