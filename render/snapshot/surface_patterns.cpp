// Pattern surfaces and the colour of a checker or an image at a hit.
#include "snapshot/surface_patterns.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "texture/checker.h"
#include "texture/shape_uv.h"

namespace rs {

namespace {

/// The surface for a shape in world space already (planes: the document keeps them so).
PatternSurface identitySurface(PatternSurface::Shape shape) {
    PatternSurface s;
    s.shape = shape;
    return s;
}

/// One triangle accel per mesh data with texture coordinates, kept while something uses it,
/// so a snapshot rebuilt on every move does not rebuild the mesh's BVH.
std::shared_ptr<const MeshAccel> uvAccelFor(const std::shared_ptr<const MeshData>& data) {
    static std::mutex mutex;
    static std::map<const MeshData*,
                    std::pair<std::weak_ptr<const MeshData>, std::weak_ptr<const MeshAccel>>>
        known;
    std::lock_guard lock(mutex);
    std::erase_if(known, [](const auto& entry) { return entry.second.second.expired(); });
    auto& slot = known[data.get()];
    if (slot.first.lock() == data)
        if (auto accel = slot.second.lock()) return accel;
    auto accel = std::make_shared<const MeshAccel>(data, false);
    slot = {data, accel};
    return accel;
}

/// The file's first UV channel at object-space point `po` (world normal `n`), interpolated
/// over the triangle under it; (0, 0) with no gradient when the mesh has no texture
/// coordinates or no triangle lies there.
ShapeUV meshUV(const PatternSurface& surface, const Vec3& po, const Vec3& n) {
    ShapeUV uv{0.0f, 0.0f, Vec3(0.0f), Vec3(0.0f)};
    if (!surface.mesh) return uv;
    const Vec3 no = glm::normalize(surface.normalToObject * n);
    uint32_t tri = 0;
    float b1 = 0.0f, b2 = 0.0f;
    if (!surface.mesh->triangleAt(po, no, tri, b1, b2)) return uv;
    const MeshData& data = *surface.mesh->data();
    const uint32_t* i = &data.indices[3 * std::size_t(tri)];
    return triangleUV(data.positions[i[0]], data.positions[i[1]], data.positions[i[2]],
                      data.uvs[i[0]], data.uvs[i[1]], data.uvs[i[2]], b1, b2);
}

}  // namespace

PatternSurface SurfacePatterns::surfaceOf(const Object& o,
                                          const std::shared_ptr<const MeshData>& meshData) {
    PatternSurface s;
    if (const auto* plane = std::get_if<PlaneGeometry>(&o.geometry)) {
        s = identitySurface(PatternSurface::Shape::Plane);
        s.a = plane->point;
        s.b = glm::normalize(plane->normal);
        s.planeAxes = planeAxes(s.b);
        return s;
    }
    const Mat4 worldFromObject = o.transform.matrix();
    s.objectFromWorld = glm::inverse(worldFromObject);
    s.dirToObject = Mat3(s.objectFromWorld);
    s.normalToObject = glm::transpose(Mat3(worldFromObject));
    if (const auto* sphere = std::get_if<SphereGeometry>(&o.geometry)) {
        s.shape = PatternSurface::Shape::Sphere;
        s.a = sphere->center;
        s.r = sphere->radius;
    } else if (const auto* rect = std::get_if<RectangleGeometry>(&o.geometry)) {
        s.shape = PatternSurface::Shape::Rectangle;
        s.a = rect->center, s.b = rect->u, s.c = rect->v;
    } else if (const auto* box = std::get_if<BoxGeometry>(&o.geometry)) {
        s.shape = PatternSurface::Shape::Box;
        s.a = box->min, s.b = box->max;
    } else {
        s.shape = PatternSurface::Shape::Mesh;
        const auto* mesh = std::get_if<MeshGeometry>(&o.geometry);
        const auto& data = meshData ? meshData : mesh ? mesh->data : meshData;
        if (data && !data->uvs.empty() && data->uvs.size() == data->positions.size())
            s.mesh = uvAccelFor(data);
    }
    return s;
}

void SurfacePatterns::resize(std::size_t primitives, std::size_t planes) {
    primitives_.assign(primitives, PatternSurface{});
    planes_.assign(planes, identitySurface(PatternSurface::Shape::Plane));
}

void CheckerBatch::reset(std::size_t capacity) {
    count_ = 0;
    // Room for whole lanes: evaluate() pads the last one.
    capacity = (capacity + kLaneWidth - 1) / kLaneWidth * kLaneWidth;
    if (entries_.size() >= capacity) return;
    entries_.resize(capacity);
    for (auto* v : {&px_, &py_, &pz_, &hx_, &hy_, &hz_, &scale_, &odd_}) v->resize(capacity);
}

const float* CheckerBatch::evaluate() {
    // The last lane's spare places repeat the last point (their answers are not read).
    const std::size_t lanes = kLaneWidth;
    for (std::size_t k = count_; k % lanes != 0; ++k) entries_[k] = entries_[count_ - 1];
    for (std::size_t first = 0; first < count_; first += lanes) {
        FloatLanes dx, dy, dz, nx, ny, nz, width;
        for (std::size_t k = 0; k < lanes; ++k) {
            const Entry& e = entries_[first + k];
            dx[k] = e.dir.x, dy[k] = e.dir.y, dz[k] = e.dir.z;
            nx[k] = e.n.x, ny[k] = e.n.y, nz[k] = e.n.z;
            width[k] = e.width;
        }
        FootprintAxes<FloatLanes> f = footprintAxes(dx, dy, dz, nx, ny, nz, width);
        // Into each surface's own space (inObject), point by point: planes need nothing.
        for (std::size_t k = 0; k < lanes; ++k) {
            const std::size_t i = first + k;
            const Entry& e = entries_[i];
            Vec3 p = e.p;
            if (e.surface) {
                const InObject o = inObject(
                    *e.surface, e.p,
                    {Vec3(f.a1x[k], f.a1y[k], f.a1z[k]), Vec3(f.a2x[k], f.a2y[k], f.a2z[k])});
                p = o.p;
                f.a1x[k] = o.a1.x, f.a1y[k] = o.a1.y, f.a1z[k] = o.a1.z;
                f.a2x[k] = o.a2.x, f.a2y[k] = o.a2.y, f.a2z[k] = o.a2.z;
            }
            px_[i] = p.x, py_[i] = p.y, pz_[i] = p.z;
            scale_[i] = e.scale;
        }
        storeLanes(&hx_[first], boxHalfWidth(f.a1x, f.a2x));
        storeLanes(&hy_[first], boxHalfWidth(f.a1y, f.a2y));
        storeLanes(&hz_[first], boxHalfWidth(f.a1z, f.a2z));
    }
    checkerOddFractions(
        count_,
        {px_.data(), py_.data(), pz_.data(), hx_.data(), hy_.data(), hz_.data(), scale_.data()},
        odd_.data());
    return odd_.data();
}

Color patternColor(const MaterialPattern& pattern, const PatternSurface& surface, Vec3 p, Vec3 n,
                   Vec3 dir, float width) {
    if (pattern.kind == MaterialPattern::Kind::Checker) {
        const CheckerBox box = checkerBoxAt(surface, p, footprintAt(dir, n, width));
        return checkerColor(pattern,
                            checkerOddFraction(box.p, box.halfWidth, pattern.checkerScale));
    }
    // inObject's point and half-axes, the axes kept as vector lanes: held as Vec3s through
    // the calls below, they were spilt and reloaded in pieces that straddled each other, a
    // store-forwarding stall a lookup.
    const FootprintAxes<float> f = footprintAxes(dir.x, dir.y, dir.z, n.x, n.y, n.z, width);
    Vec3 po = p;
    FloatLanes a1{f.a1x, f.a1y, f.a1z, 0.0f}, a2{f.a2x, f.a2y, f.a2z, 0.0f};
    if (surface.shape != PatternSurface::Shape::Plane) {
        const InObject o =
            inObject(surface, p, {Vec3(f.a1x, f.a1y, f.a1z), Vec3(f.a2x, f.a2y, f.a2z)});
        po = o.p;
        a1 = FloatLanes{o.a1.x, o.a1.y, o.a1.z, 0.0f};
        a2 = FloatLanes{o.a2.x, o.a2.y, o.a2.z, 0.0f};
    }
    ShapeUV uv{0.0f, 0.0f, Vec3(0.0f), Vec3(0.0f)};
    switch (surface.shape) {
        case PatternSurface::Shape::Sphere:
            uv = sphereUV(po, surface.a, surface.r);
            break;
        case PatternSurface::Shape::Plane:
            uv = planeUV(po, surface.a, surface.planeAxes);
            break;
        case PatternSurface::Shape::Rectangle:
            uv = rectangleUV(po, surface.a, surface.b, surface.c);
            break;
        case PatternSurface::Shape::Box:
            uv = boxUV(po, glm::normalize(surface.normalToObject * n), surface.a, surface.b);
            break;
        case PatternSurface::Shape::Mesh:
            uv = meshUV(surface, po, n);
            break;
    }
    // Texture coordinates (s, t) with t = 0 the image's top row; a pixel's derivatives are
    // the full footprint (twice its half-axes).
    const float su = pattern.scaleU, sv = pattern.scaleV;
    const float s = uv.u * su + pattern.offsetU;
    const float t = 1.0f - (uv.v * sv + pattern.offsetV);
    const Vec3 b1(a1[0], a1[1], a1[2]), b2(a2[0], a2[1], a2[2]);
    const float dsdx = 2.0f * glm::dot(uv.dudp, b1) * su, dtdx = -2.0f * glm::dot(uv.dvdp, b1) * sv;
    const float dsdy = 2.0f * glm::dot(uv.dudp, b2) * su, dtdy = -2.0f * glm::dot(uv.dvdp, b2) * sv;
    if (!pattern.texture) return missingTexture(s, t);
    return TextureStore::shared().lookup(pattern.texture, s, t, dsdx, dtdx, dsdy, dtdy);
}

}  // namespace rs
