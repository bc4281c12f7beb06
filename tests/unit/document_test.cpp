// Document model: stable ids and transform order.
#include "scene/document.h"

#include <gtest/gtest.h>

namespace rs {

TEST(Document, AddObject_AssignsFreshIdsThatAreNeverReused) {
    SceneDocument doc;
    auto named = [](const char* name) {
        Object o;
        o.name = name;
        return o;
    };
    ObjectId a = doc.addObject(named("a"));
    ObjectId b = doc.addObject(named("b"));
    EXPECT_NE(a, b);
    doc.objects.erase(doc.objects.begin());
    ObjectId c = doc.addObject(named("c"));
    EXPECT_NE(c, a);
    EXPECT_EQ(doc.findObject(b)->name, "b");
    EXPECT_EQ(doc.findObject(a), nullptr);
}

TEST(Document, TransformMatrix_RotatesXThenYThenZ) {
    Transform t;
    t.rotate = Vec3(90.0f, 90.0f, 0.0f);
    // X first takes +y to +z, then Y takes +z to +x.
    Vec3 p = Vec3(t.matrix() * glm::vec4(0, 1, 0, 1));
    EXPECT_NEAR(p.x, 1.0f, 1e-5f);
    EXPECT_NEAR(p.y, 0.0f, 1e-5f);
    EXPECT_NEAR(p.z, 0.0f, 1e-5f);
}

TEST(Document, TransformMatrix_ScalesBeforeTranslating) {
    Transform t;
    t.translate = Vec3(1, 2, 3);
    t.scale = Vec3(2.0f);
    Vec3 p = Vec3(t.matrix() * glm::vec4(1, 1, 1, 1));
    EXPECT_EQ(p, Vec3(3, 4, 5));
}

}  // namespace rs
