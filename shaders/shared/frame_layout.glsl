// The lighting pass's per-frame data, laid out once for both sides: the GPU reads the frame's
// constants from a std140 uniform block and the rest from std430 shader storage buffers; the CPU
// (render/frame_data.h) fills the same structs (render/shared_shading.h checks their sizes and
// offsets). Every member is a scalar, vec2, vec3 followed by a scalar, vec4 or mat4 in an order
// where std140, std430 and C++ agree, with explicit padding to whole vec4s: no hand-kept mirror.
// Integers are ints on both sides (never floats to round back).
//
// Batches. A frame evaluates batchCount batches of four wavelengths; batch b holds the
// wavelengths and the rows of its integration matrix (observer or camera response over
// n·pdf, times 683 lm/W), so tristimulus += (toX·L, toY·L, toZ·L) for the batch's radiance L.
// In RGB mode there is one batch whose four "wavelengths" are the R, G, B channels (and a zero).
//
// Spectra. Flat arrays of vec4 (one batch each), indexed by the helpers below, which both sides
// call: a light's normalised SPD (the light after the last, lightCount, is the background's
// radiance); a material's measured reflectance (j = 0) or its conductor n (j = 0) and k (j = 1),
// and, under its own index, its emitted radiance (j = 0).
//
// Techniques. Each technique declares its own block (constants and per-batch data) in its own
// shared header (underwater.glsl, atmosphere_model.glsl) and packs it on the CPU
// (techniques/technique_section.h): nothing of theirs is here.

const int kModeRgb = 0;
const int kModeNaive = 1;        // box upsampling (495 / 570 nm)
const int kModeJakobHanika = 2;  // sigmoid upsampling; the reference mode too, with many batches

const int kMaterialBaseColour = 0;  // upsampled base colour (texture × factor)
const int kMaterialMeasured = 1;    // measured spectral reflectance
const int kMaterialConductor = 2;   // n, k per wavelength (in RGB mode: Schlick with F0 in j = 0)

const int kMaxLights = 16;

// The G-buffer's material id: the material's index + 1, 0 where no geometry is, and with this bit
// set where the object is one a technique shades itself in its forward pass after the lighting
// pass (techniques/technique_pass.h, drawForward: PRT objects). The lighting pass lights those by
// the scene's lights alone, as Lambertian surfaces (SurfaceSample::techniqueShaded); the
// technique adds its own light (PRT's environment) on top.
const uint kTechniqueShadedBit = 0x80000000u;

struct GpuBatch {
  vec4 lambdaNm;
  vec4 toX;
  vec4 toY;
  vec4 toZ;
};

const int kMaxShadowCascades = 4;  // a directional light's shadow-map layers at most

struct GpuLight {
  vec3 positionW;          // point, spot
  int type;                // kLight* (lights.glsl)
  vec3 direction;          // of travel, unit (directional, spot)
  float intensity;         // lux (directional) or candela (point, spot)
  float cosInner;          // spot: cosine of the inner half-angle
  float cosOuter;          // spot: cosine of the outer half-angle
  int shadowLayer;         // layer of the shadow-map array (point: the first of six); < 0: none
  float shadowNormalOffsetM;
  float shadowDepthBias;
  float shadowFaceScale;   // point: its six faces' pointShadowProjection, x, y, z
  float shadowDepthA;
  float shadowDepthB;
  mat4 shadowFromWorld;    // world → the light's clip space (directional: its whole-scene map's; spot)
  // Directional: its cascades' windows over shadowFromWorld's clip x, y (shadowCascadeFromWorld),
  // finest first, one layer each from shadowLayer; the last is the whole scene's, (0, 0, 1).
  // Other lights: one window, (0, 0, 1).
  vec4 shadowCascades[kMaxShadowCascades];
  int shadowCascadeCount;
  int pad0;
  int pad1;
  int pad2;
};

struct GpuMaterial {
  vec3 baseColour;  // linear RGB factor (× the texture)
  float metallic;
  float roughness;
  int kind;         // kMaterial*
  int spectra;      // index of its spectra (measured and conductor kinds)
  int lambertian;   // 1: the diffuse lobe alone
  // Index of its emitted radiance's spectra (j = 0 of materialSpectrumIndex; RGB mode: its colour
  // in cd/m²), or kNoEmission.
  int emission;
  // glTF's emission (the G-buffer's emissive colour, SurfaceSample::emission): the index of the
  // colour space's white of luminance 1 (RGB mode: (1, 1, 1)), or kNoEmission; and the cd/m² of
  // the colour (1, 1, 1).
  int rgbEmissionWhite;
  float rgbEmissionLuminance;
  int pad0;
};
const int kNoEmission = -1;

// The lighting pass's per-frame constants: one std140 uniform block on the GPU (binding
// kFrameConstantsBinding), the same struct on the CPU.
const int kFrameConstantsBinding = 0;
struct FrameConstants {
  mat4 inverseViewProjection;  // clip → world, of the frame's camera
  vec3 cameraPositionW;
  int mode;                    // kMode*
  vec2 viewportSize;           // pixels
  int batchCount;
  int lightCount;              // ≤ kMaxLights
  int shadowMapSize;           // texels along each side of a shadow-map layer
  int gbufferCoefficients;     // 1: the G-buffer holds Jakob–Hanika coefficients (upsamplingCoefficients reads them)
  int upsamplingResolution;    // of the Jakob–Hanika table, per side
  int filteredLookup;          // 1: one filtered fetch of the table; 0: the manual blend
};

PRISM_INLINE int lightSpectrumIndex(int light, int batch, int batchCount) {
  return light * batchCount + batch;
}
PRISM_INLINE int materialSpectrumIndex(int spectra, int batch, int j, int batchCount) {
  return (spectra * batchCount + batch) * 2 + j;
}

// One G-buffer sample.

struct SurfaceSample {
  vec3 position;   // world
  vec3 normal;     // world, unit
  vec3 albedo;     // linear RGB (texture × factor)
  vec3 emission;   // glTF's emissive colour, linear RGB (GpuMaterial::rgbEmissionWhite)
  float metallic;
  float roughness;
  int material;    // index into the material table
  bool techniqueShaded;  // a technique's object: Lambertian, lit by the scene's lights only
};
