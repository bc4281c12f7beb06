// describeChange: each kind of edit is named, with the objects and fields it changed.
#include "scene/document_change.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "test_scenes.h"

namespace rs {
namespace {

using test::manySpheres;

TEST(DocumentChange, MovingOneOfManyObjects_NamesThatObjectAndItsShapeAlone) {
    const SceneDocument before = manySpheres(10000);
    SceneDocument after = before;
    const std::size_t index = 6543;
    const ObjectId id = std::as_const(after).objects[index].id;
    after.findObject(id)->transform.translate.y = 1.0f;
    // The copy shares every chunk of objects but the moved one's.
    std::size_t unshared = 0;
    for (std::size_t c = 0; c < after.objects.chunkCount(); ++c)
        unshared += after.objects.sharesChunk(before.objects, c) ? 0 : 1;
    EXPECT_EQ(unshared, 1u);

    const DocumentChange c = describeChange(before, after);
    EXPECT_FALSE(c.camera || c.render || c.materials || c.lights || c.environment || c.extras);
    EXPECT_FALSE(c.objectsRestructured);
    ASSERT_EQ(c.objects.size(), 1u);
    EXPECT_EQ(c.objects[0].id, id);
    EXPECT_EQ(c.objects[0].index, index);
    EXPECT_EQ(c.objects[0].fields, DocumentChange::kShape);
    EXPECT_TRUE(c.any());
    EXPECT_FALSE(describeChange(before, before).any());
}

TEST(DocumentChange, EachFieldAndPart_IsNamed) {
    const SceneDocument before = manySpheres(300);
    const ObjectId a = before.objects[10].id, b = before.objects[200].id;
    SceneDocument after = before;
    after.findObject(a)->name = "renamed";
    after.findObject(a)->visible = false;
    after.findObject(b)->material = "red";
    after.findObject(b)->extras.push_back({"x-note", "1"});
    DocumentChange c = describeChange(before, after);
    ASSERT_EQ(c.objects.size(), 2u);
    EXPECT_EQ(c.objects[0].id, a);
    EXPECT_EQ(c.objects[0].fields, DocumentChange::kName | DocumentChange::kVisible);
    EXPECT_EQ(c.objects[1].id, b);
    EXPECT_EQ(c.objects[1].fields, DocumentChange::kMaterial | DocumentChange::kExtras);
    EXPECT_EQ(c.objectFields(), 0x1e);

    SceneDocument parts = before;
    parts.camera.fovY = 40.0f;
    parts.materials[0].diffuse = 0.5f;
    parts.lights[0].intensity = 2.0f;
    c = describeChange(before, parts);
    EXPECT_TRUE(c.camera && c.materials && c.lights);
    EXPECT_FALSE(c.render || c.environment || c.objectsRestructured || !c.objects.empty());
}

TEST(DocumentChange, AddingRemovingOrReorderingObjects_IsARestructure) {
    const SceneDocument before = manySpheres(300);
    SceneDocument added = before;
    Object extra;
    extra.name = "new";
    added.addObject(extra);
    EXPECT_TRUE(describeChange(before, added).objectsRestructured);
    SceneDocument removed = before;
    removed.objects.erase(removed.objects.begin() + 5);
    EXPECT_TRUE(describeChange(before, removed).objectsRestructured);
    SceneDocument swapped = before;
    std::swap(swapped.objects[3], swapped.objects[4]);
    const DocumentChange c = describeChange(before, swapped);
    EXPECT_TRUE(c.objectsRestructured);
    EXPECT_TRUE(c.objects.empty());
    EXPECT_TRUE(DocumentChange::everything().objectsRestructured);
}

}  // namespace
}  // namespace rs
