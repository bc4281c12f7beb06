// The one test of a bounded primitive against a world-space ray.
#include "accel/primitive.h"

namespace rs {

namespace {

/// Tests one bounded shape against a ray given in the shape's own frame.
bool intersectShape(const BoundedShape& shape, const Ray& ray, float tmin, float tmax,
                    ShapeHit& hit) {
    return std::visit(
        [&](const auto& s) -> bool {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, MeshShape>) {
                return s.accel->intersect(ray, tmin, tmax, hit);
            } else {
                return rs::intersect(s, ray, tmin, tmax, hit);
            }
        },
        shape);
}

}  // namespace

bool intersectPrimitive(const Primitive& p, const Ray& ray, float tmin, float tmax, ShapeHit& hit) {
    if (!p.hasFrame) return intersectShape(p.shape, ray, tmin, tmax, hit);
    // Test in the object's frame: t is unchanged because the direction is mapped linearly too.
    const Frame& f = p.frame;
    const Ray local = Ray::make(f.pointToObject(ray.origin), f.directionToObject(ray.dir));
    if (!intersectShape(p.shape, local, tmin, tmax, hit)) return false;
    hit.n = glm::normalize(f.normalToWorld * hit.n);
    return true;
}

}  // namespace rs
