// Stateless random numbers for per-pixel, per-frame sampling: the same seed gives the same
// number on the CPU and the GPU.
// Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3), the PCG hash (pcg).

PRISM_INLINE uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// The top 24 bits as a float in [0, 1): exact in single precision, never 1.
PRISM_INLINE float uintToUnitFloat(uint v) { return float(v >> 8u) * (1.0f / 16777216.0f); }

// The index-th number of the stream named by seed (e.g. a hash of pixel and frame).
PRISM_INLINE float randomFloat(uint seed, uint index) {
  return uintToUnitFloat(pcgHash(seed ^ pcgHash(index)));
}
