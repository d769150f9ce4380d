// Loader fixture: the file beside the includer wins over other/shadow.glsl in an include folder.
PRISM_INLINE uint shadow() { return 1000u; }
