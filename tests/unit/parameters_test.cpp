// Parameter descriptors: every kind publishes typed, ranged inputs bound to the document.
#include "scene/parameters.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rs {
namespace {

TEST(Parameters, EveryKind_PublishesDescriptorsWithDefaultsOfTheirType) {
    for (int k = 0; k <= int(ParamKind::Render); ++k) {
        const auto& list = parameters(ParamKind(k));
        EXPECT_FALSE(list.empty()) << kindLabel(ParamKind(k));
        for (const auto& d : list) {
            EXPECT_TRUE(validateParameter(d, d.defaultValue).empty()) << d.key;
            EXPECT_FALSE(d.label.empty());
        }
    }
}

TEST(Parameters, SphereRadius_GetAndSetRoundTrip) {
    Geometry g = SphereGeometry{Vec3(1, 2, 3), 0.5f};
    EXPECT_EQ(std::get<float>(*getParameter(g, "radius")), 0.5f);
    EXPECT_TRUE(setParameter(g, "radius", 2.0f).empty());
    EXPECT_EQ(std::get<SphereGeometry>(g).radius, 2.0f);
    EXPECT_EQ(std::get<Vec3>(*getParameter(g, "center")), Vec3(1, 2, 3));
}

TEST(Parameters, OutOfRangeValue_IsRejectedWithMessageAndLeavesTargetUnchanged) {
    Geometry g = SphereGeometry{};
    const std::string e = setParameter(g, "radius", 0.0f);
    EXPECT_NE(e.find("radius"), std::string::npos);
    EXPECT_EQ(std::get<SphereGeometry>(g).radius, 1.0f);

    Material m;
    EXPECT_FALSE(setParameter(m, "diffuse", 1.5f).empty());
    EXPECT_FALSE(setParameter(m, "color", Vec3(-1, 0, 0)).empty());
    EXPECT_EQ(m.diffuse, 1.0f);
}

TEST(Parameters, WrongValueType_IsRejected) {
    Material m;
    EXPECT_FALSE(setParameter(m, "diffuse", 1).empty());
    EXPECT_FALSE(setParameter(m, "no_such_key", 1.0f).empty());
}

TEST(Parameters, ReflectivityPlusTransparencyAboveOne_IsRejected) {
    Material m;
    ASSERT_TRUE(setParameter(m, "transparency", 0.9f).empty());
    EXPECT_FALSE(setParameter(m, "reflectivity", 0.5f).empty());
    EXPECT_EQ(m.reflectivity, 0.0f);
}

TEST(Parameters, PlaneNormal_IsNormalisedAndZeroIsRejected) {
    Geometry g = PlaneGeometry{};
    ASSERT_TRUE(setParameter(g, "normal", Vec3(0, 0, 0.5f)).empty());
    EXPECT_EQ(std::get<PlaneGeometry>(g).normal, Vec3(0, 0, 1));
    EXPECT_FALSE(setParameter(g, "normal", Vec3(0)).empty());
}

TEST(Parameters, SphereLight_HasRadiusAndPointLightDoesNot) {
    Light l;
    EXPECT_EQ(findParameter(lightKind(l), "radius"), nullptr);
    ASSERT_TRUE(setParameter(l, "type", int(LightType::Sphere)).empty());
    EXPECT_EQ(lightKind(l), ParamKind::SphereLight);
    EXPECT_NE(findParameter(lightKind(l), "radius"), nullptr);
    EXPECT_TRUE(setParameter(l, "radius", 0.25f).empty());
    EXPECT_EQ(l.radius, 0.25f);
}

TEST(Parameters, RenderMinWeight_IsPublishedWithItsDefaultAndRangeBelowOne) {
    const ParamDescriptor* d = findParameter(ParamKind::Render, "min_weight");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->type, ParamType::Float);
    EXPECT_EQ(std::get<float>(d->defaultValue), 1.0f / 255.0f);
    RenderSettings r;
    EXPECT_EQ(std::get<float>(*getParameter(r, "min_weight")), 1.0f / 255.0f);
    EXPECT_TRUE(setParameter(r, "min_weight", 0.0f).empty());
    EXPECT_EQ(r.minWeight, 0.0f);
    EXPECT_TRUE(setParameter(r, "min_weight", std::nextafter(1.0f, 0.0f)).empty());
    EXPECT_FALSE(setParameter(r, "min_weight", 1.0f).empty());
    EXPECT_FALSE(setParameter(r, "min_weight", -0.5f).empty());
    EXPECT_EQ(r.minWeight, std::nextafter(1.0f, 0.0f));
}

TEST(Parameters, EnumsAndInts_AreRangeChecked) {
    RenderSettings r;
    EXPECT_TRUE(setParameter(r, "tonemap", 3).empty());
    EXPECT_EQ(r.tonemap, ToneMap::Aces);
    EXPECT_FALSE(setParameter(r, "tonemap", 4).empty());
    EXPECT_FALSE(setParameter(r, "width", 0).empty());
    const ParamDescriptor* d = findParameter(ParamKind::Render, "tonemap");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->enumNames.size(), 4u);
}

TEST(Parameters, CameraTargetEqualToPosition_IsRejected) {
    Camera c;
    EXPECT_FALSE(setParameter(c, "target", c.position).empty());
    EXPECT_TRUE(setParameter(c, "fov_y", 40.0f).empty());
    EXPECT_FALSE(setParameter(c, "fov_y", 180.0f).empty());
}

TEST(Parameters, GeometryKind_FollowsTheVariant) {
    EXPECT_EQ(geometryKind(Geometry{BoxGeometry{}}), ParamKind::Box);
    EXPECT_EQ(geometryKind(Geometry{MeshGeometry{}}), ParamKind::Mesh);
    Transform t;
    EXPECT_TRUE(setParameter(t, "translate", Vec3(1, 2, 3)).empty());
    EXPECT_EQ(t.translate, Vec3(1, 2, 3));
    EXPECT_FALSE(setParameter(t, "scale", Vec3(0, 1, 1)).empty());
}

}  // namespace
}  // namespace rs
