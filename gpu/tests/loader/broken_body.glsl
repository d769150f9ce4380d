// Loader fixture: a deliberate type error, on the line marked below.

PRISM_INLINE float fine(float x) { return 2.0f * x; }

PRISM_INLINE float broken(float x) {
  return fine(x) * vec2(1.0f);  // BROKEN: float function returning vec2
}
