// Document model: stable ids and transform order.
#include "scene/document.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

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

TEST(Document, FindObject_FindsEveryIdInAnyOrder_AndNothingForAnAbsentId) {
    SceneDocument doc;
    std::vector<ObjectId> ids;
    for (int i = 0; i < 1000; ++i) {
        Object o;
        o.name = "o";
        o.name += std::to_string(i);
        ids.push_back(doc.addObject(o));
        if (i % 3 == 0) doc.addLight(Light{});  // ids interleave between the two lists
    }
    doc.objects.eraseIf([](const Object& o) { return o.id % 7 == 0; });  // deletions
    for (ObjectId id : ids) {
        const Object* o = doc.findObject(id);
        if (id % 7 == 0) {
            EXPECT_EQ(o, nullptr) << id;
        } else {
            ASSERT_NE(o, nullptr) << id;
            EXPECT_EQ(o->id, id);
        }
    }
    for (const Light& l : doc.lights) EXPECT_EQ(doc.findLight(l.id), &l);
    EXPECT_EQ(doc.findObject(doc.nextId), nullptr);
    EXPECT_EQ(doc.findLight(ids[1]), nullptr);  // an object's id is no light's
    // A list someone reordered is still searched correctly (only more slowly).
    std::vector<Object> reversed = doc.objects.toVector();
    std::reverse(reversed.begin(), reversed.end());
    doc.objects = SharedList<Object>(reversed);
    for (const Object& o : std::as_const(doc).objects)
        EXPECT_EQ(std::as_const(doc).findObject(o.id), &o);
}

}  // namespace rs
