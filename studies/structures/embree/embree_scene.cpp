#include "studies/structures/embree/embree_scene.h"

#include <stdexcept>
#include <string>

namespace raystep {

namespace {

void check(RTCDevice device, const char* step) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) {
        throw std::runtime_error(std::string("Embree failed at ") + step + " (error " +
                                 std::to_string(error) + ")");
    }
}

// A buffer of `count` items of `format` that Embree allocates; Embree pads vertex buffers so that
// its 16-byte loads of the last float3 stay inside.
template <class T>
T* new_buffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, std::size_t item_bytes,
              std::size_t count) {
    void* buffer = rtcSetNewGeometryBuffer(geometry, type, 0, format, item_bytes, count);
    if (!buffer) throw std::runtime_error("Embree could not allocate a geometry buffer");
    return static_cast<T*>(buffer);
}

// Attaches the committed geometry to the scene and lets go of our reference; its id.
unsigned attach(RTCScene scene, RTCGeometry geometry) {
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    return id;
}

}  // namespace

EmbreeScene::EmbreeScene(std::shared_ptr<RTCDeviceTy> device, const PrimitiveList& primitives)
    : device_(std::move(device)), sphere_count_(primitives.spheres.size()) {
    RTCDevice d = device_.get();
    scene_ = rtcNewScene(d);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);

    // Spheres: x, y, z, radius
    if (!primitives.spheres.empty()) {
        RTCGeometry geometry = rtcNewGeometry(d, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* points = new_buffer<float>(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT4,
                                         4 * sizeof(float), primitives.spheres.size());
        for (const Sphere& s : primitives.spheres) {
            *points++ = static_cast<float>(s.center.x);
            *points++ = static_cast<float>(s.center.y);
            *points++ = static_cast<float>(s.center.z);
            *points++ = static_cast<float>(s.radius);
        }
        sphere_geometry_ = attach(scene_, geometry);
    }

    // Triangles: our list is a triangle soup, so triangle k has vertices 3k, 3k + 1, 3k + 2
    if (!primitives.triangles.empty()) {
        const std::size_t count = primitives.triangles.size();
        RTCGeometry geometry = rtcNewGeometry(d, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = new_buffer<float>(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3,
                                           3 * sizeof(float), 3 * count);
        auto* indices = new_buffer<unsigned>(geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT3,
                                             3 * sizeof(unsigned), count);
        unsigned next = 0;
        for (const Triangle& t : primitives.triangles) {
            for (const Vec3& p : {t.p0, t.p1, t.p2}) {
                *vertices++ = static_cast<float>(p.x);
                *vertices++ = static_cast<float>(p.y);
                *vertices++ = static_cast<float>(p.z);
                *indices++ = next++;
            }
        }
        triangle_geometry_ = attach(scene_, geometry);
    }
    check(d, "setting up the scene");
}

EmbreeScene::~EmbreeScene() {
    rtcReleaseScene(scene_);
}

void EmbreeScene::build() {
    rtcCommitScene(scene_);
    check(device_.get(), "rtcCommitScene");
}

void EmbreeScene::closest_hits(const Ray* rays, std::size_t count, BenchHit* answers,
                               TraversalStats*) const {
    // One context for the batch: rtcIntersect1 leaves it as it found it
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t k = 0; k < count; ++k) {
        const Ray& ray = rays[k];
        RTCRayHit query;
        query.ray.org_x = static_cast<float>(ray.origin.x);
        query.ray.org_y = static_cast<float>(ray.origin.y);
        query.ray.org_z = static_cast<float>(ray.origin.z);
        query.ray.tnear = static_cast<float>(ray.t_min);
        query.ray.dir_x = static_cast<float>(ray.direction.x);
        query.ray.dir_y = static_cast<float>(ray.direction.y);
        query.ray.dir_z = static_cast<float>(ray.direction.z);
        query.ray.time = 0.0f;
        query.ray.tfar = static_cast<float>(ray.t_max);
        query.ray.mask = ~0u;
        query.ray.id = 0;
        query.ray.flags = 0;
        query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &query);

        if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
            answers[k] = BenchHit{};
            continue;
        }
        const std::size_t first = query.hit.geomID == sphere_geometry_ ? 0 : sphere_count_;
        answers[k] = {static_cast<std::uint32_t>(first + query.hit.primID), query.ray.tfar};
    }
}

}  // namespace raystep
