// The lighting pass's per-frame data, laid out once for both sides: the GPU reads these structs
// from std430 shader storage buffers, the CPU (render/frame_data.h) fills arrays of the same
// structs (C++ checks their sizes). Only vec4 and mat4 members, so std430 and C++ agree with
// no padding.
//
// Batches. A frame evaluates batchCount batches of four wavelengths; batch b holds the
// wavelengths and the rows of its integration matrix (observer or camera response over
// n·pdf, times 683 lm/W), so tristimulus += (toX·L, toY·L, toZ·L) for the batch's radiance L.
// In RGB mode there is one batch whose four "wavelengths" are the R, G, B channels (and a zero).
//
// Spectra. lightSpectra[l·batchCount + b] is light l's normalised SPD at batch b's wavelengths
// (l = lightCount is the background's radiance); materialSpectra[(s·batchCount + b)·2 + j] is a
// material's measured reflectance (j = 0) or its conductor n (j = 0) and k (j = 1);
// waterSpectra[b·3 + j] is the water's σs (j = 0), σt (j = 1) and Kd (j = 2) in 1/m (in RGB mode
// at 680, 550 and 440 nm).

const int kModeRgb = 0;
const int kModeNaive = 1;        // box upsampling (495 / 570 nm)
const int kModeJakobHanika = 2;  // sigmoid upsampling; the reference mode too, with many batches

const int kMaterialBaseColour = 0;  // upsampled base colour (texture × factor)
const int kMaterialMeasured = 1;    // measured spectral reflectance
const int kMaterialConductor = 2;   // n, k per wavelength (in RGB mode: Schlick with F0 in j = 0)

const int kMaxLights = 16;

struct GpuBatch {
  vec4 lambdaNm;
  vec4 toX;
  vec4 toY;
  vec4 toZ;
};

struct GpuLight {
  vec4 positionType;        // xyz position (point, spot); w type (kLight*)
  vec4 directionIntensity;  // xyz direction of travel (unit); w intensity (lux or cd)
  vec4 cone;                // x cos of inner half-angle, y cos of outer; zw unused
  vec4 shadow;              // x shadow-map layer (< 0: none), y normal offset (m), z depth bias
  mat4 shadowFromWorld;     // world → the light's clip space
};

struct GpuMaterial {
  vec4 baseColourMetallic;  // linear RGB factor, metallic
  vec4 roughnessKind;       // x roughness, y kind (kMaterial*), z spectra index, w 1: Lambertian
};

// Per-frame constants of the lighting pass (uniforms on the GPU) and one G-buffer sample.
struct FrameConstants {
  int mode;           // kMode*
  int batchCount;
  int lightCount;     // ≤ kMaxLights
  int shadowMapSize;  // texels along each side of a shadow-map layer
  int water;          // 1: the camera is under water (underwater.glsl; waterSpectra below)
  float waterDepthM;  // the camera's depth below the water surface
  float waterSurfaceY;  // world height of the water surface (m)
  int gbufferCoefficients;  // 1: the G-buffer holds Jakob–Hanika coefficients (upsamplingCoefficients reads them)
  int atmosphere;           // 1: the scene has a sky (atmosphere_lighting.glsl; frameAtmosphere(b))
  int atmosphereSunLight;   // index of the light that is the atmosphere's sun
  float atmosphereOriginKm; // distance of the world's origin from the planet's centre
};

struct SurfaceSample {
  vec3 position;   // world
  vec3 normal;     // world, unit
  vec3 albedo;     // linear RGB (texture × factor)
  float metallic;
  float roughness;
  int material;    // index into the material table
};
