// Out-of-line parts of the math types.
#include "core/math.h"

namespace rs {

Aabb Aabb::transformed(const Mat4& m) const {
    Aabb out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        Vec3 corner((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
        out.expand(Vec3(m * glm::vec4(corner, 1.0f)));
    }
    return out;
}

}  // namespace rs
