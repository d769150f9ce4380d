#include "rays/triangle_bvh.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "core/error.h"
#include "core/parallel_for.h"

namespace prism::rays {
namespace {

const char* embreeErrorName(RTCError error) {
  switch (error) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
  }
  return "error";
}

void check(RTCDevice device, const char* what) {
  RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw Error(fmt::format("Embree: {} failed ({})", what, embreeErrorName(error)));
  }
}

RTCRay makeRay(const glm::vec3& origin, const glm::vec3& direction, float tMin, float tMax) {
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.tnear = tMin;
  ray.tfar = tMax;
  ray.mask = std::numeric_limits<unsigned>::max();
  return ray;
}

// Attaches one mesh's copy to the scene; the geometry is released on every path.
void attach(RTCDevice device, RTCScene scene, const TriangleMesh& mesh) {
  PRISM_CHECK(mesh.indices.size() % 3 == 0);
  PRISM_CHECK(std::all_of(mesh.indices.begin(), mesh.indices.end(),
                          [&](std::uint32_t i) { return i < mesh.positions.size(); }));
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  check(device, "rtcNewGeometry");
  try {
    auto* positions = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.indices.size() / 3));
    check(device, "allocating a mesh's buffers");
    if (!positions || !indices) throw Error("Embree: allocating a mesh's buffers failed");
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      std::memcpy(positions + 3 * i, &mesh.positions[i], 3 * sizeof(float));
    }
    std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(unsigned));
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, mesh.id);
    check(device, "adding a mesh");
  } catch (...) {
    rtcReleaseGeometry(geometry);
    throw;
  }
  rtcReleaseGeometry(geometry);
}

}  // namespace

struct TriangleBvh::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  Handles() = default;
  Handles(const Handles&) = delete;
  Handles& operator=(const Handles&) = delete;
  ~Handles() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

TriangleBvh::TriangleBvh(std::span<const TriangleMesh> meshes) : mHandles(std::make_unique<Handles>()) {
  // Its BVH builds on as many threads as the process's work (prism validate --threads caps both).
  mHandles->device = rtcNewDevice(fmt::format("threads={}", allThreads()).c_str());
  if (!mHandles->device) {
    throw Error(fmt::format("Embree: cannot create a device ({})", embreeErrorName(rtcGetDeviceError(nullptr))));
  }
  mHandles->scene = rtcNewScene(mHandles->device);
  check(mHandles->device, "rtcNewScene");
  for (const TriangleMesh& mesh : meshes) {
    if (!mesh.indices.empty()) attach(mHandles->device, mHandles->scene, mesh);
  }
  rtcSetSceneBuildQuality(mHandles->scene, RTC_BUILD_QUALITY_HIGH);
  rtcCommitScene(mHandles->scene);
  check(mHandles->device, "building the BVH");
}

TriangleBvh::~TriangleBvh() = default;
TriangleBvh::TriangleBvh(TriangleBvh&&) noexcept = default;
TriangleBvh& TriangleBvh::operator=(TriangleBvh&&) noexcept = default;

std::optional<TriangleHit> TriangleBvh::intersect(const glm::vec3& origin, const glm::vec3& direction,
                                                  float tMin, float tMax) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit{};
  rayHit.ray = makeRay(origin, direction, tMin, tMax);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(mHandles->scene, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return TriangleHit{rayHit.ray.tfar, rayHit.hit.geomID, rayHit.hit.primID, rayHit.hit.u, rayHit.hit.v};
}

bool TriangleBvh::occluded(const glm::vec3& origin, const glm::vec3& direction, float tMin,
                           float tMax) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = makeRay(origin, direction, tMin, tMax);
  rtcOccluded1(mHandles->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to −∞ on a hit
}

}  // namespace prism::rays
