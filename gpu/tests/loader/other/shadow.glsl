// Loader fixture: must never be chosen for main.comp's #include "shadow.glsl".
PRISM_INLINE uint shadow() { return 7u; }
