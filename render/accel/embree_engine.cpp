// Embree 3 scenes from a SceneGeometry, the user-geometry callbacks, and packet queries.
#include "accel/embree_engine.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

namespace rs {

namespace {

void reportError(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "raystudio: Embree error %d: %s\n", int(code), message ? message : "");
}

/// One device for the process: Embree's thread pool and memory are shared by every scene.
RTCDevice device() {
    static RTCDevice dev = [] {
        RTCDevice d = rtcNewDevice(nullptr);
        if (!d) throw std::runtime_error("Embree: cannot create a device");
        rtcSetDeviceErrorFunction(d, reportError, nullptr);
        return d;
    }();
    return dev;
}

const EmbreeEngine& engineOf(void* userPtr) {
    return *static_cast<const EmbreeEngine*>(userPtr);
}

void boundsCallback(const RTCBoundsFunctionArguments* args) {
    const Aabb& b = engineOf(args->geometryUserPtr).userPrimitive(args->primID).worldBounds;
    args->bounds_o->lower_x = b.min.x, args->bounds_o->lower_y = b.min.y;
    args->bounds_o->lower_z = b.min.z;
    args->bounds_o->upper_x = b.max.x, args->bounds_o->upper_y = b.max.y;
    args->bounds_o->upper_z = b.max.z;
}

/// The lane's ray as the project's Ray (with the reciprocals the box test uses).
Ray laneRay(RTCRayN* ray, unsigned N, unsigned i) {
    return Ray::make(
        Vec3(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i)),
        Vec3(RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i)));
}

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
    const Primitive& p = engineOf(args->geometryUserPtr).userPrimitive(args->primID);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        float& tfar = RTCRayN_tfar(ray, args->N, i);
        ShapeHit sh;
        // The open range (0, tfar) of every engine; origins are offset by the caller.
        if (!intersectPrimitive(p, laneRay(ray, args->N, i), 0.0f, tfar, sh)) continue;
        tfar = sh.t;
        RTCHitN_Ng_x(hit, args->N, i) = sh.n.x;
        RTCHitN_Ng_y(hit, args->N, i) = sh.n.y;
        RTCHitN_Ng_z(hit, args->N, i) = sh.n.z;
        RTCHitN_u(hit, args->N, i) = 0.0f;
        RTCHitN_v(hit, args->N, i) = 0.0f;
        RTCHitN_primID(hit, args->N, i) = args->primID;
        RTCHitN_geomID(hit, args->N, i) = args->geomID;
        RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
    }
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
    const Primitive& p = engineOf(args->geometryUserPtr).userPrimitive(args->primID);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        float& tfar = RTCRayN_tfar(args->ray, args->N, i);
        ShapeHit sh;
        if (intersectPrimitive(p, laneRay(args->ray, args->N, i), 0.0f, tfar, sh))
            tfar = -kInfinity;  // Embree's mark for an occluded ray
    }
}

constexpr int kPacket = 8;

/// One packet of Embree's own SoA layout. The fields Embree reads but never writes (tnear,
/// time, mask, id, flags) are set once when the packet is made, not for every eight rays.
struct alignas(32) Packet {
    int valid[kPacket];
    RTCRayHit8 rh;

    Packet() {
        for (int k = 0; k < kPacket; ++k) {
            rh.ray.tnear[k] = 0.0f;
            rh.ray.time[k] = 0.0f;
            rh.ray.mask[k] = 0xffffffffu;
            rh.ray.id[k] = unsigned(k);
            rh.ray.flags[k] = 0;
        }
    }
};

/// Fills lanes [0, n) of `p` from rays [first, first + n): a full packet is eight contiguous
/// floats of each of the batch's arrays, copied as they lie; a short one repeats its first
/// ray in the lanes it leaves off. `bound` (may be null) gives a ray's far end instead of
/// tmax where `slot` holds a hit (the planes' answer, which bounds the tree's walk).
void loadPacket(Packet& p, const RayBatch& rays, std::size_t first, int n,
                const HitBatch* bound = nullptr) {
    auto& r = p.rh.ray;
    if (n == kPacket) {
        const std::size_t bytes = kPacket * sizeof(float);
        std::memcpy(r.org_x, rays.ox + first, bytes), std::memcpy(r.org_y, rays.oy + first, bytes);
        std::memcpy(r.org_z, rays.oz + first, bytes), std::memcpy(r.dir_x, rays.dx + first, bytes);
        std::memcpy(r.dir_y, rays.dy + first, bytes), std::memcpy(r.dir_z, rays.dz + first, bytes);
        std::memcpy(r.tfar, rays.tmax + first, bytes);
        for (int k = 0; k < kPacket; ++k) p.valid[k] = -1;
    } else {
        for (int k = 0; k < kPacket; ++k) {
            const bool on = k < n;
            p.valid[k] = on ? -1 : 0;
            const std::size_t i = first + std::size_t(on ? k : 0);
            r.org_x[k] = rays.ox[i], r.org_y[k] = rays.oy[i], r.org_z[k] = rays.oz[i];
            r.dir_x[k] = rays.dx[i], r.dir_y[k] = rays.dy[i], r.dir_z[k] = rays.dz[i];
            r.tfar[k] = rays.tmax[i];
        }
    }
    if (bound)
        for (int k = 0; k < n; ++k) {
            const std::size_t i = first + std::size_t(k);
            if (bound->slot[i] != kNoSlot) r.tfar[k] = bound->t[i];
        }
    for (int k = 0; k < kPacket; ++k) {
        p.rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        p.rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
}

}  // namespace

struct EmbreeMesh {
    std::shared_ptr<const MeshAccel> accel;
    RTCScene scene = nullptr;

    explicit EmbreeMesh(std::shared_ptr<const MeshAccel> a) : accel(std::move(a)) {
        const MeshData& data = *accel->data();
        scene = rtcNewScene(device());
        // Not RTC_SCENE_FLAG_ROBUST: measured 2-3x slower on a 1M-triangle mesh, and the
        // built-in engine's Moeller-Trumbore is not watertight either (parity tests agree).
        RTCGeometry geom = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_TRIANGLE);
        // Copies: Embree may read 16 bytes at the last vertex, past the end of the data.
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
            std::max<std::size_t>(1, data.positions.size())));
        if (!data.positions.empty())
            std::memcpy(vertices, data.positions.data(), data.positions.size() * sizeof(Vec3));
        const std::size_t triangles = data.triangleCount();
        auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles));
        for (std::size_t t = 0; t < triangles; ++t) {
            // An out-of-range index becomes a degenerate triangle, never hit (as MeshAccel).
            const bool valid = accel->validTriangle(uint32_t(t));
            for (int k = 0; k < 3; ++k) indices[3 * t + k] = valid ? data.indices[3 * t + k] : 0u;
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
    }
    ~EmbreeMesh() { rtcReleaseScene(scene); }
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;
};

/// World spheres in a committed scene of their own (instanced by the top level): the ones that
/// have not moved since updated() split them off.
struct EmbreeStillSpheres {
    RTCScene scene = nullptr;
    std::vector<uint32_t> prims;  ///< Primitive index of each sphere primID.

    /// The world spheres of `prims` whose index is not in `moved` (sorted).
    EmbreeStillSpheres(const std::vector<Primitive>& all, const std::vector<uint32_t>& moved) {
        for (uint32_t i = 0; i < all.size(); ++i)
            if (!all[i].hasFrame && std::holds_alternative<SphereShape>(all[i].shape) &&
                !std::binary_search(moved.begin(), moved.end(), i))
                prims.push_back(i);
        scene = rtcNewScene(device());
        attachSpheres(scene, all, prims);
        rtcCommitScene(scene);
    }
    ~EmbreeStillSpheres() { rtcReleaseScene(scene); }
    EmbreeStillSpheres(const EmbreeStillSpheres&) = delete;
    EmbreeStillSpheres& operator=(const EmbreeStillSpheres&) = delete;

    /// Embree's sphere primitive for each of `which`, tested in SIMD inside its BVH leaves (no
    /// callback); returns the geometry's id in `scene`.
    static unsigned attachSpheres(RTCScene scene, const std::vector<Primitive>& all,
                                  const std::vector<uint32_t>& which) {
        RTCGeometry spheres = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(spheres, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                              which.size()));
        for (std::size_t k = 0; k < which.size(); ++k) {
            const SphereShape& s = std::get<SphereShape>(all[which[k]].shape);
            v[4 * k] = s.center.x, v[4 * k + 1] = s.center.y, v[4 * k + 2] = s.center.z;
            v[4 * k + 3] = std::abs(s.radius);
        }
        rtcCommitGeometry(spheres);
        const unsigned id = rtcAttachGeometry(scene, spheres);
        rtcReleaseGeometry(spheres);
        return id;
    }
};

EmbreeEngine::EmbreeEngine(const SceneGeometry& geometry, const EmbreeEngine* previous)
    : geometry_(geometry) {
    const auto& prims = *geometry_.primitives;
    // A few world spheres: eight lanes against each of them cost less than Embree's packet
    // traversal of a tree over them (callgrind, reference room: 98 M against 158 M
    // instructions a frame), so such a scene is answered by the flat set alone, as the
    // built-in engine does.
    flatOnly_ = FlatSet::suits(prims);
    hasPlanes_ = !geometry_.planes->empty();
    planes_ = FlatSet(*geometry_.planes, flatOnly_ ? &prims : nullptr);
    scene_ = rtcNewScene(device());
    if (flatOnly_) {
        rtcCommitScene(scene_);
        return;
    }
    buildTopLevel(previous, nullptr);
}

EmbreeEngine::EmbreeEngine(const SceneGeometry& geometry, const EmbreeEngine* previous,
                           std::vector<uint32_t> moved,
                           std::shared_ptr<const EmbreeStillSpheres> still)
    : geometry_(geometry), still_(std::move(still)) {
    hasPlanes_ = !geometry_.planes->empty();
    planes_ = FlatSet(*geometry_.planes, nullptr);
    scene_ = rtcNewScene(device());
    buildTopLevel(previous, &moved);
}

void EmbreeEngine::buildTopLevel(const EmbreeEngine* previous, const std::vector<uint32_t>* moved) {
    const auto& prims = *geometry_.primitives;
    std::unordered_map<const MeshAccel*, std::shared_ptr<const EmbreeMesh>> known;
    if (previous)
        for (const auto& m : previous->meshes_)
            if (m) known.emplace(m->accel.get(), m);
    meshes_.resize(prims.size());
    for (uint32_t i = 0; i < prims.size(); ++i) {
        const auto* mesh = std::get_if<MeshShape>(&prims[i].shape);
        if (!mesh) {
            const bool worldSphere =
                !prims[i].hasFrame && std::holds_alternative<SphereShape>(prims[i].shape);
            if (!worldSphere)
                userPrims_.push_back(i);
            else if (!moved || std::binary_search(moved->begin(), moved->end(), i))
                spherePrims_.push_back(i);
            continue;
        }
        auto& slot = known[mesh->accel.get()];
        if (!slot) slot = std::make_shared<const EmbreeMesh>(mesh->accel);
        meshes_[i] = slot;
        RTCGeometry inst = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(inst, slot->scene);
        rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                                &prims[i].frame.worldFromObject[0][0]);
        rtcCommitGeometry(inst);
        const unsigned id = rtcAttachGeometry(scene_, inst);
        rtcReleaseGeometry(inst);
        if (instances_.size() <= id) instances_.resize(id + 1);
        MeshInstance& mi = instances_[id];
        mi.slot = i;
        mi.mesh = mesh->accel.get();
        mi.smooth = mesh->accel->smooth();
        mi.frame = &prims[i].frame;
        // A translation, or a uniform scale without rotation: no matrix work a hit.
        const Mat3& m = mi.frame->dirToObject;
        mi.scaleOnly = m[0][0] > 0.0f && m[0][0] == m[1][1] && m[1][1] == m[2][2] &&
                       m[0][1] == 0.0f && m[0][2] == 0.0f && m[1][0] == 0.0f && m[1][2] == 0.0f &&
                       m[2][0] == 0.0f && m[2][1] == 0.0f;
    }
    if (!userPrims_.empty()) {
        RTCGeometry user = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(user, unsigned(userPrims_.size()));
        rtcSetGeometryUserData(user, this);
        rtcSetGeometryBoundsFunction(user, boundsCallback, this);
        rtcSetGeometryIntersectFunction(user, intersectCallback);
        rtcSetGeometryOccludedFunction(user, occludedCallback);
        rtcCommitGeometry(user);
        userGeomID_ = rtcAttachGeometry(scene_, user);
        rtcReleaseGeometry(user);
    }
    if (!spherePrims_.empty())
        sphereGeomID_ = EmbreeStillSpheres::attachSpheres(scene_, prims, spherePrims_);
    if (still_) {
        // Placed as it is: Embree's identity transform leaves the rays' bits as they are.
        RTCGeometry inst = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(inst, still_->scene);
        const Mat4 identity(1.0f);
        rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &identity[0][0]);
        rtcCommitGeometry(inst);
        stillInstID_ = rtcAttachGeometry(scene_, inst);
        rtcReleaseGeometry(inst);
    }
    rtcCommitScene(scene_);
}

std::size_t EmbreeEngine::stillSpheres() const {
    return still_ ? still_->prims.size() : 0;
}

EmbreeEngine::~EmbreeEngine() {
    rtcReleaseScene(scene_);
}

std::shared_ptr<const RayEngine> EmbreeEngine::updated(const SceneGeometry& geometry,
                                                       std::span<const uint32_t> moved) const {
    // The top level holds one entry per object (mesh instances, user primitives): committing
    // a new one is O(objects) and leaves every mesh's triangle scene as it is. Many world
    // spheres are one entry, and a tree over 100,000 of them took 20 ms to build per move:
    // the unmoved ones stay in a scene this engine shares.
    const auto& prims = *geometry.primitives;
    const std::size_t spheres = spherePrims_.size() + (still_ ? still_->prims.size() : 0);
    const auto isWorldSphere = [](const Primitive& p) {
        return !p.hasFrame && std::holds_alternative<SphereShape>(p.shape);
    };
    bool split = !flatOnly_ && spheres >= kSplitSpheres && moved.size() <= kMaxMovedSpheres &&
                 prims.size() == geometry_.primitives->size();
    for (std::size_t k = 0; split && k < moved.size(); ++k)
        split = moved[k] < prims.size() && isWorldSphere(prims[moved[k]]) &&
                isWorldSphere((*geometry_.primitives)[moved[k]]);
    if (!split) return std::make_shared<const EmbreeEngine>(geometry, this);

    // The spheres moved since the shared scene was built, and these.
    std::vector<uint32_t> apart(moved.begin(), moved.end());
    if (still_) apart.insert(apart.end(), spherePrims_.begin(), spherePrims_.end());
    std::sort(apart.begin(), apart.end());
    apart.erase(std::unique(apart.begin(), apart.end()), apart.end());
    std::shared_ptr<const EmbreeStillSpheres> still = still_;
    if (!still_ || apart != spherePrims_) {
        if (apart.size() > kMaxMovedSpheres) {
            apart.assign(moved.begin(), moved.end());
            std::sort(apart.begin(), apart.end());
            apart.erase(std::unique(apart.begin(), apart.end()), apart.end());
        }
        still = std::make_shared<const EmbreeStillSpheres>(prims, apart);
    }
    return std::shared_ptr<const EmbreeEngine>(
        new EmbreeEngine(geometry, this, std::move(apart), std::move(still)));
}

inline float EmbreeEngine::MeshInstance::distance(const Vec3& ng, const Vec3& v0,
                                                  const RayBatch& rays, std::size_t i,
                                                  float tEmbree, float tmax) const {
    // Embree moves the ray into the object's frame with an inverse of its own, which differs
    // from the frame's objectFromWorld in the last bits; at grazing angles that shifts t by
    // up to ~3e-5 relative (engine parity test). The distance to the plane of Embree's
    // triangle along the frame's own object-space ray, as the built-in engine tests it,
    // agrees with its Moeller-Trumbore to ~2e-6 (the same test, measured).
    const Vec3 o(rays.ox[i], rays.oy[i], rays.oz[i]), d(rays.dx[i], rays.dy[i], rays.dz[i]);
    Vec3 ol, dl;
    if (scaleOnly) {
        const float s = frame->dirToObject[0][0];
        ol = s * o + Vec3(frame->objectFromWorld[3]), dl = s * d;
    } else {
        // The built-in engine's object-space ray (intersectPrimitive), bit for bit.
        ol = frame->pointToObject(o), dl = frame->directionToObject(d);
    }
    const float t = glm::dot(ng, v0 - ol) / glm::dot(ng, dl);
    // Embree's answer stands where the plane's leaves the ray's open range (0, tmax): a ray
    // (nearly) in the triangle's plane, whose distance is then no better than Embree's.
    return t > 0.0f && t < tmax ? t : tEmbree;
}

inline Vec3 EmbreeEngine::MeshInstance::toWorld(const Vec3& n) const {
    return glm::normalize(scaleOnly ? n : frame->normalToWorld * n);
}

void EmbreeEngine::closestHit(const RayBatch& rays, const HitBatch& hits) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags =
        rays.coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    const auto& prims = *geometry_.primitives;
    // Planes first, with the same rule as every engine: their t bounds the tree's walk.
    // Without planes the loop below writes every ray's answer, misses included.
    if (hasPlanes_ || flatOnly_) planes_.closestHit(rays, hits);
    if (flatOnly_) return;
    Packet p;
    for (std::size_t first = 0; first < rays.count; first += kPacket) {
        const int n = int(std::min<std::size_t>(kPacket, rays.count - first));
        loadPacket(p, rays, first, n, hasPlanes_ ? &hits : nullptr);
        rtcIntersect8(p.valid, scene_, &context, &p.rh);
        for (int k = 0; k < n; ++k) {
            const std::size_t i = first + std::size_t(k);
            const unsigned inst = p.rh.hit.instID[0][k];
            Vec3 normal;
            uint32_t slot;
            const bool stillSphere = inst != RTC_INVALID_GEOMETRY_ID && inst == stillInstID_;
            if (inst != RTC_INVALID_GEOMETRY_ID && !stillSphere) {
                const MeshInstance& mi = instances_[inst];
                slot = mi.slot;
                const uint32_t tri = p.rh.hit.primID[k];
                // Embree's triangle, barycentrics and object-space geometric normal.
                const Vec3 ng(p.rh.hit.Ng_x[k], p.rh.hit.Ng_y[k], p.rh.hit.Ng_z[k]);
                // The far end Embree was given: the planes' hit, else the ray's own.
                const float tmax = hasPlanes_ && hits.slot[i] != kNoSlot ? hits.t[i] : rays.tmax[i];
                p.rh.ray.tfar[k] =
                    mi.distance(ng, mi.mesh->firstVertex(tri), rays, i, p.rh.ray.tfar[k], tmax);
                normal = mi.smooth ? mi.toWorld(mi.mesh->normal(tri, p.rh.hit.u[k], p.rh.hit.v[k]))
                                   : mi.toWorld(ng);
            } else if (stillSphere || (p.rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID &&
                                       p.rh.hit.geomID[k] == sphereGeomID_)) {
                slot = stillSphere ? still_->prims[p.rh.hit.primID[k]]
                                   : spherePrims_[p.rh.hit.primID[k]];
                // The outward normal from the centre, as intersect(SphereShape) defines it.
                const SphereShape& s = std::get<SphereShape>(prims[slot].shape);
                const Vec3 o(rays.ox[i], rays.oy[i], rays.oz[i]),
                    d(rays.dx[i], rays.dy[i], rays.dz[i]);
                normal = divide((o - s.center) + p.rh.ray.tfar[k] * d, s.radius);
            } else if (p.rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID) {
                slot = userPrims_[p.rh.hit.primID[k]];
                normal = Vec3(p.rh.hit.Ng_x[k], p.rh.hit.Ng_y[k], p.rh.hit.Ng_z[k]);
            } else if (hasPlanes_) {
                continue;  // the plane's answer (or none) stands
            } else {
                hits.t[i] = kInfinity;  // FlatSet's miss
                hits.nx[i] = hits.ny[i] = hits.nz[i] = 0.0f;
                hits.slot[i] = kNoSlot;
                continue;
            }
            hits.t[i] = p.rh.ray.tfar[k];
            hits.nx[i] = normal.x, hits.ny[i] = normal.y, hits.nz[i] = normal.z;
            hits.slot[i] = slot;
        }
    }
}

void EmbreeEngine::anyHit(const RayBatch& rays, uint8_t* occluded) const {
    if (flatOnly_) return planes_.anyHit(rays, occluded);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags =
        rays.coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    Packet p;
    for (std::size_t first = 0; first < rays.count; first += kPacket) {
        const int n = int(std::min<std::size_t>(kPacket, rays.count - first));
        loadPacket(p, rays, first, n);
        // Bounded objects first: a shadow ray toward a light inside a room never reaches a wall.
        rtcOccluded8(p.valid, scene_, &context, &p.rh.ray);
        for (int k = 0; k < n; ++k)
            occluded[first + std::size_t(k)] = p.rh.ray.tfar[k] == -kInfinity;
    }
    planes_.anyHit(rays, occluded, /*skipBlocked=*/true);
}

}  // namespace rs
