// Document model: stable ids and transform order.
#include "scene/document.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/id_search.h"

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
}

TEST(Document, IdLookup_AMissReadsAFewIds_NotTheWholeList) {
    // No selection, the camera or a light's id asked of the objects: each of those misses
    // read all 100,000 objects' ids once per property-panel refresh.
    SceneDocument doc;
    for (int i = 0; i < 4096; ++i) {
        doc.addObject(Object{});
        if (i % 5 == 0) doc.addLight(Light{});
    }
    std::size_t reads = 0;
    const auto idOf = [&reads](const Object& o) {
        ++reads;
        return o.id;
    };
    const std::size_t bound = 2 * 12 + 2;  // two reads per halving of 4096, and the last one
    for (ObjectId missing : {kNoObject, doc.lights[7].id, doc.nextId, ObjectId(0xFFFFFFFFu)}) {
        reads = 0;
        EXPECT_EQ(indexById(doc.objects, missing, idOf), -1) << missing;
        EXPECT_LE(reads, bound) << missing;
    }
    reads = 0;
    const ObjectId present = doc.objects[1234].id;
    EXPECT_EQ(indexById(doc.objects, present, idOf), 1234);
    EXPECT_LE(reads, bound);
}

}  // namespace rs
