// The session invariant over every kind of edit the designer can make: after random rotations,
// scales, geometry parameters, smooth-normal toggles, exposure and tone map, render settings,
// material edits and reassignments, checkers and textures, the environment, spot and sun
// lights (besides moves and point-light edits), the refined frame equals a
// from-scratch render in colour, and a from-scratch session's frame in object id, depth and
// normal, with both engines, on a scene of boxes, rectangles, a smooth mesh, scaled spheres
// and a sphere light; and after dragging glass and a mirror under a sun.
#include <gtest/gtest.h>

#include <random>

#include "edit_scenes.h"
#include "integrator/renderer.h"
#include "io/scene_io.h"
#include "session/render_session.h"

namespace rs {
namespace {

using namespace std::chrono_literals;
const std::string kScenes = RAYSTUDIO_SCENES_DIR;

SceneDocument invariantRoom() {
    SceneDocument doc = test::editRoom(64, 48);
    for (Object& o : doc.objects.editable())
        if (o.name == "mirror ball") o.transform.scale = Vec3(1.0f, 0.8f, 1.2f);  // own frame
    doc.render.supersampling = 4;
    doc.render.adaptiveSupersampling = true;
    return doc;
}

struct FrameCopy {
    std::vector<Color> color;
    std::vector<ObjectId> id;
    std::vector<float> depth;
    std::vector<Vec3> normal;
};

FrameCopy copyFrame(const RenderSession& session) {
    FrameCopy c;
    session.withFrame([&](const DeepFrame& f, const auto&) {
        c.color.assign(f.color().begin(), f.color().end());
        c.id.assign(f.id().begin(), f.id().end());
        c.depth.assign(f.depth().begin(), f.depth().end());
        c.normal.assign(f.normal().begin(), f.normal().end());
    });
    return c;
}

/// Compares the edited session's frame with a full render (colour) and with the frame of a
/// new session given only the final document (id, depth, normal).
void expectMatchesFromScratch(const RenderSession& session, const SceneDocument& doc,
                              EngineKind engine, const std::string& where) {
    const FrameCopy edited = copyFrame(session);
    session.withFrame([&](const DeepFrame& f, const auto&) {
        EXPECT_TRUE(f.summariesMatchPixels()) << where << ": tile counts and summaries";
    });
    const RenderResult full = renderImage(CompiledScene(doc, nullptr, engine));
    RenderSession fresh(2);
    fresh.setEngine(engine);
    fresh.update(doc);
    ASSERT_TRUE(fresh.waitUntilComplete(60s));
    const FrameCopy scratch = copyFrame(fresh);
    ASSERT_EQ(edited.color.size(), full.image.pixels.size()) << where;
    ASSERT_EQ(edited.color.size(), scratch.color.size()) << where;
    float worstColor = 0.0f, worstDepth = 0.0f, worstNormal = 0.0f;
    std::size_t ids = 0, fullIds = 0;
    for (std::size_t i = 0; i < edited.color.size(); ++i) {
        const Color d = glm::abs(edited.color[i] - full.image.pixels[i]);
        worstColor = std::max({worstColor, d.x, d.y, d.z});
        ids += edited.id[i] != scratch.id[i];
        fullIds += edited.id[i] != full.ids[i];
        if (std::isinf(edited.depth[i]) || std::isinf(scratch.depth[i])) {
            worstDepth =
                std::max(worstDepth, edited.depth[i] == scratch.depth[i] ? 0.0f : kInfinity);
        } else {
            worstDepth = std::max(worstDepth, std::abs(edited.depth[i] - scratch.depth[i]) /
                                                  std::max(1.0f, scratch.depth[i]));
            const Vec3 n = glm::abs(edited.normal[i] - scratch.normal[i]);
            worstNormal = std::max({worstNormal, n.x, n.y, n.z});
        }
    }
    EXPECT_LE(worstColor, 1e-5f) << where << ": colour";
    EXPECT_EQ(ids, 0u) << where << ": object ids against a fresh session";
    EXPECT_EQ(fullIds, 0u) << where << ": object ids against a full render";
    EXPECT_LE(worstDepth, 1e-5f) << where << ": depth";
    EXPECT_LE(worstNormal, 1e-5f) << where << ": normal";
}

Object& randomBounded(SceneDocument& doc, std::mt19937& rng) {
    std::vector<Object*> bounded;
    for (Object& o : doc.objects.editable())
        if (!std::holds_alternative<PlaneGeometry>(o.geometry)) bounded.push_back(&o);
    return *bounded[rng() % bounded.size()];
}

/// A random edit of a kind the older invariant (session_test.cpp) does not make.
void randomEdit(SceneDocument& doc, std::mt19937& rng, std::string& kind) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Object& o = randomBounded(doc, rng);
    switch (rng() % 14) {
        case 0:
            kind = "rotate " + o.name;
            o.transform.rotate += Vec3(25.0f * u(rng), 40.0f * u(rng), 15.0f * u(rng));
            break;
        case 1:
            kind = "scale " + o.name;
            o.transform.scale *= Vec3(1.0f + 0.25f * u(rng), 1.0f + 0.25f * u(rng), 1.0f);
            break;
        case 2:  // the object's own geometry keys
            kind = "geometry of " + o.name;
            if (auto* s = std::get_if<SphereGeometry>(&o.geometry)) {
                s->radius *= 1.0f + 0.2f * u(rng);
                s->center.x += 0.2f * u(rng);
            } else if (auto* b = std::get_if<BoxGeometry>(&o.geometry)) {
                b->max += Vec3(0.15f * std::abs(u(rng)), 0.1f * std::abs(u(rng)), 0.0f);
            } else if (auto* r = std::get_if<RectangleGeometry>(&o.geometry)) {
                r->u *= 1.0f + 0.3f * u(rng);
                r->center.y += 0.1f * u(rng);
            } else if (auto* m = std::get_if<MeshGeometry>(&o.geometry)) {
                m->smoothNormals = !m->smoothNormals;
            }
            break;
        case 3:
            kind = "smooth normals";
            for (Object& any : doc.objects.editable())
                if (auto* m = std::get_if<MeshGeometry>(&any.geometry))
                    m->smoothNormals = !m->smoothNormals;
            break;
        case 4:
            kind = "exposure and tone map";
            doc.render.exposure = 2.0f * u(rng);
            doc.render.tonemap = ToneMap(rng() % 4);
            break;
        case 5:
            kind = "render settings";
            switch (rng() % 5) {
                case 0:
                    doc.render.maxDepth = 1 + int(rng() % 4);
                    break;
                case 1:
                    doc.render.shadowSamples = int(rng() % 5);
                    break;
                case 2:
                    doc.render.background = Color(0.2f + 0.2f * u(rng), 0.3f, 0.4f);
                    break;
                case 3:
                    doc.render.ambient = Color(0.05f + 0.04f * u(rng));
                    break;
                default:
                    doc.render.minWeight = rng() % 2 ? 0.0f : 0.02f;
                    break;
            }
            break;
        case 6: {
            kind = "material parameters";
            Material& m = doc.materials[rng() % doc.materials.size()];
            m.specular = 0.5f + 0.5f * u(rng);
            m.shininess = 40.0f + 30.0f * u(rng);
            if (m.transparency > 0.0f) m.ior = 1.3f + 0.2f * std::abs(u(rng));
            if (m.reflectivity > 0.0f) m.reflectivity = 0.5f + 0.4f * std::abs(u(rng));
            break;
        }
        case 7:
            kind = "reassign material of " + o.name;
            o.material = doc.materials[rng() % doc.materials.size()].name;
            break;
        case 8:
            kind = "checker on a material";
            {
                Material& m = doc.materials[rng() % doc.materials.size()];
                CheckerPattern c;
                c.even = Color(0.9f, 0.2f + 0.2f * u(rng), 0.1f);
                c.odd = Color(0.1f, 0.2f, 0.8f);
                c.scale = 0.3f + 0.2f * std::abs(u(rng));
                m.pattern = c;
            }
            break;
        case 9:
            kind = "texture on a material";
            {
                Material& m = doc.materials[rng() % doc.materials.size()];
                ImageTexture t;
                t.image = {"textures/tiles.png", kScenes + "/textures/tiles.png"};
                t.scaleU = 1.0f + std::abs(u(rng));
                t.offsetV = 0.5f * u(rng);
                m.pattern = rng() % 4 ? ColorPattern(t) : ColorPattern();
            }
            break;
        case 10:
            kind = "environment";
            if (rng() % 4 == 0) {
                doc.environment = Environment{};
            } else {
                doc.environment.image = {"textures/sky.hdr", kScenes + "/textures/sky.hdr"};
                doc.environment.rotation = 180.0f * u(rng);
                doc.environment.intensity = 1.0f + 0.5f * u(rng);
            }
            break;
        case 11: {
            kind = "spot light";
            Light* spot = nullptr;
            for (Light& l : doc.lights)
                if (l.type == LightType::Spot) spot = &l;
            if (!spot) {
                Light l;
                l.name = "spot";
                l.type = LightType::Spot;
                spot = doc.findLight(doc.addLight(l));
            }
            spot->position = Vec3(0.5f * u(rng), 2.5f, 0.5f * u(rng));
            spot->target = Vec3(u(rng), 0.0f, -3.0f + u(rng));
            spot->coneRadius = 10.0f + 5.0f * std::abs(u(rng));
            spot->coneFalloff = spot->coneRadius + 10.0f * std::abs(u(rng));
            break;
        }
        case 12: {
            kind = "sun light";
            Light* sun = nullptr;
            for (Light& l : doc.lights)
                if (l.type == LightType::Directional) sun = &l;
            if (!sun) {
                Light l;
                l.name = "sun";
                l.type = LightType::Directional;
                l.intensity = 0.5f;
                sun = doc.findLight(doc.addLight(l));
            }
            sun->direction = Vec3(0.5f * u(rng), -1.0f, 0.5f * u(rng));
            break;
        }
        default:
            kind = "move " + o.name;
            o.transform.translate += Vec3(0.3f * u(rng), 0.2f * u(rng), 0.3f * u(rng));
            break;
    }
}

void runEdits(EngineKind engine, uint32_t seed) {
    SceneDocument doc = invariantRoom();
    RenderSession session(2);
    session.setEngine(engine);
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    std::mt19937 rng(seed);
    for (int round = 0; round < 6; ++round) {
        const bool drag = rng() % 2;
        if (drag) session.beginInteraction(doc.objects[2].id);
        std::string kinds;
        const int edits = 1 + int(rng() % 3);
        for (int e = 0; e < edits; ++e) {
            std::string kind;
            randomEdit(doc, rng, kind);
            kinds += kind + "; ";
            const uint64_t gen = session.update(doc);
            if (rng() % 2) session.waitForPass(gen, 30s);
        }
        if (drag) session.endInteraction();
        ASSERT_TRUE(session.waitUntilComplete(60s));
        expectMatchesFromScratch(session, doc, engine,
                                 std::string(engineName(engine)) + " seed " + std::to_string(seed) +
                                     " round " + std::to_string(round) + " after " + kinds);
    }
}

/// Drags the classic scene's glass ball (then its mirror ball) under the default interaction
/// policy (deferred shadows, dirty regions, the governor) and lets go: its sun, a light
/// kSunDistance away, casts the glass-filtered shadow over the checker floor under the sky.
void dragUnderTheSun(EngineKind engine) {
    SceneLoadResult loaded = loadScene(kScenes + "/classic.scene.json");
    ASSERT_TRUE(loaded.ok()) << loaded.errorText();
    SceneDocument doc = loaded.document;
    doc.render.width = 96;
    doc.render.height = 54;
    RenderSession session(2);
    session.setEngine(engine);
    ASSERT_EQ(session.policy(), InteractionPolicy{});
    session.update(doc);
    ASSERT_TRUE(session.waitUntilComplete(60s));
    for (const auto& [name, by] : {std::pair{"glass ball", Vec3(-0.1f, 0.075f, -0.05f)},
                                   std::pair{"mirror ball", Vec3(0.12f, 0.1f, 0.15f)}}) {
        Object* moved = nullptr;
        for (Object& o : doc.objects.editable())
            if (o.name == name) moved = &o;
        ASSERT_NE(moved, nullptr) << name;
        session.beginInteraction(moved->id);
        for (int step = 0; step < 4; ++step) {
            moved->transform.translate += by;
            ASSERT_TRUE(session.waitForPass(session.update(doc), 30s));
        }
        session.endInteraction();
        ASSERT_TRUE(session.waitUntilComplete(60s));
        expectMatchesFromScratch(session, doc, engine,
                                 std::string(engineName(engine)) + ": dragged the " + name);
    }
}

TEST(SessionInvariant, GlassAndMirrorDraggedUnderASun_Embree_FrameEqualsFromScratch) {
    dragUnderTheSun(EngineKind::Embree);
}

TEST(SessionInvariant, GlassAndMirrorDraggedUnderASun_Builtin_FrameEqualsFromScratch) {
    dragUnderTheSun(EngineKind::Builtin);
}

TEST(SessionInvariant, EveryEditKind_Embree_FrameEqualsFromScratch) {
    for (uint32_t seed : {21u, 22u, 23u, 24u}) runEdits(EngineKind::Embree, seed);
}

TEST(SessionInvariant, EveryEditKind_Builtin_FrameEqualsFromScratch) {
    for (uint32_t seed : {31u, 32u, 33u, 34u}) runEdits(EngineKind::Builtin, seed);
}

}  // namespace
}  // namespace rs
