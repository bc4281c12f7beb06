// Light sampling four samples at a time gives the bits of one at a time: the disk strata and
// the sampler's lists, on random shading points, seeds and sphere lights.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

#include "integrator/light_sampling.h"
#include "integrator/sampling.h"
#include "integrator/trace_kernel.h"
#include "pixel_rays.h"
#include "snapshot/compiled_scene.h"
#include "test_scenes.h"

namespace rs {
namespace {

uint32_t bitsOf(float v) {
    return std::bit_cast<uint32_t>(v);
}

TEST(DiskStrataLanes, EveryLaneHasTheBitsOfTheSingleSample) {
    std::mt19937 rng(11);
    for (int n : {4, 8, 9, 16, 27, 64, 100, 4096}) {
        const DiskStrata strata(n);
        for (int trial = 0; trial < 40; ++trial) {
            const uint32_t seed = rng();
            for (int k = 0; k + kLaneWidth <= strata.laned(); k += kLaneWidth) {
                FloatLanes x, y;
                strata.sampleLanes(k, seed, x, y);
                for (int j = 0; j < kLaneWidth; ++j) {
                    const Vec3 d = strata.sample(k + j, seed);
                    ASSERT_EQ(bitsOf(x[j]), bitsOf(d.x)) << "n " << n << " k " << k + j;
                    ASSERT_EQ(bitsOf(y[j]), bitsOf(d.y)) << "n " << n << " k " << k + j;
                }
            }
        }
    }
}

TEST(DiskStrataLanes, SamplesBeyondTheTableEqualTheFreeFunction) {
    // Documents built in code may ask for more samples than the format allows.
    const int n = kMaxSampleCount + 10;
    const DiskStrata strata(n);
    for (int k : {0, 1, kMaxSampleCount - 1, kMaxSampleCount, n - 1}) {
        const Vec3 a = strata.sample(k, 99u), b = stratifiedDiskSample(k, n, 99u);
        EXPECT_EQ(bitsOf(a.x), bitsOf(b.x));
        EXPECT_EQ(bitsOf(a.y), bitsOf(b.y));
    }
}

TEST(SinCosQuarterLanes, EveryLaneHasTheBitsOfTheScalarAndIsNearTheLibrary) {
    // The disk mapping's sin and cos: four lanes of different angles against each alone, and
    // both within 2 ulp (plus a tiny absolute slack near sin's zero) of std::sin / std::cos.
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(-kPi / 4.0f, kPi / 4.0f);
    for (int trial = 0; trial < 20000; ++trial) {
        const FloatLanes a{u(rng), u(rng), trial == 0 ? 0.0f : u(rng),
                           trial == 0 ? kPi / 4.0f : u(rng)};
        FloatLanes s, c;
        sinCosQuarter(a, s, c);
        for (int k = 0; k < kLaneWidth; ++k) {
            float sk, ck;
            sinCosQuarter(a[k], sk, ck);
            ASSERT_EQ(bitsOf(s[k]), bitsOf(sk)) << "lane " << k << " a " << a[k];
            ASSERT_EQ(bitsOf(c[k]), bitsOf(ck)) << "lane " << k << " a " << a[k];
            const float ls = std::sin(a[k]), lc = std::cos(a[k]);
            ASSERT_LE(std::abs(sk - ls), 2.0f * std::abs(std::nextafter(ls, 2.0f) - ls) + 1e-30f)
                << a[k];
            ASSERT_LE(std::abs(ck - lc), 2.0f * std::abs(std::nextafter(lc, 2.0f) - lc)) << a[k];
        }
    }
}

TEST(DiskStrataLanes, SamplesAreTheConcentricMappingWithinRounding) {
    // The polynomial stands for sin and cos of phi in both branches of Shirley-Chiu's mapping:
    // every sample within 1e-6 of the mapping evaluated with the library's sin and cos (the
    // pre-polynomial form; a swapped branch or sin/cos is off by up to the disk's diameter).
    std::mt19937 rng(31);
    for (int n : {1, 4, 9, 16, 27, 64}) {
        const DiskStrata strata(n);
        for (int trial = 0; trial < 200; ++trial) {
            const uint32_t seed = rng();
            for (int k = 0; k < n; ++k) {
                const float jx = hashToUnit(hashCombine(seed, uint32_t(2 * k)));
                const float jy = hashToUnit(hashCombine(seed, uint32_t(2 * k + 1)));
                const float sx = 2.0f * (float(k % strata.cols) + jx) / float(strata.cols) - 1.0f;
                const float sy = 2.0f * (float(k / strata.cols) + jy) / float(strata.rows) - 1.0f;
                const bool wide = std::abs(sx) > std::abs(sy);
                const float r = wide ? sx : sy;
                const float phi =
                    wide ? kPi / 4.0f * (sy / sx) : kPi / 2.0f - kPi / 4.0f * (sx / sy);
                const Vec3 d = strata.sample(k, seed);
                ASSERT_NEAR(d.x, r * std::cos(phi), 1e-6f) << "n " << n << " k " << k;
                ASSERT_NEAR(d.y, r * std::sin(phi), 1e-6f) << "n " << n << " k " << k;
            }
        }
    }
}

/// A scene of a point light and three sphere lights, `samples` shadow samples.
SceneDocument lightsScene(std::mt19937& rng, int samples) {
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    SceneDocument doc;
    doc.render.shadowSamples = samples;
    test::addMaterial(doc, "m", Color(0.8f), 0.9f);
    test::addPlane(doc, "floor", Vec3(0, -3, 0), Vec3(0, 1, 0), "m");
    test::addPointLight(doc, "point", Vec3(u(rng), u(rng), u(rng)));
    for (int i = 0; i < 3; ++i) {
        Light l;
        l.name = "sphere " + std::to_string(i);
        l.type = LightType::Sphere;
        l.radius = 0.1f + 0.3f * std::abs(u(rng));
        l.position = Vec3(u(rng), u(rng), u(rng));
        doc.addLight(l);
    }
    return doc;
}

TEST(LightSamplerLanes, FourAtATimeListsTheBitsOfOneAtATime) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::size_t compared = 0, unlisted = 0;
    for (int samples : {1, 3, 4, 5, 8, 16, 27, 64}) {
        const SceneDocument doc = lightsScene(rng, samples);
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        const LightSampler four(scene, LightSampler::Lanes::Four);
        const LightSampler one(scene, LightSampler::Lanes::One);
        for (int trial = 0; trial < 600; ++trial) {
            // Points anywhere, the lights' own centres included, normals any way round.
            Vec3 p(u(rng), u(rng), u(rng));
            if (trial % 50 == 0) p = scene.lights()[1].position;
            const Vec3 n = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0.0f, 1e-3f, 0.0f));
            const uint32_t seed = rng();
            for (bool area : {true, false}) {
                LightSamples s4, s1;
                LightSpans p4, p1;
                four.sample(p, n, seed, area, s4, p4);
                one.sample(p, n, seed, area, s1, p1);
                ASSERT_EQ(s4.size(), s1.size());
                ASSERT_EQ(p4.size(), p1.size());
                for (std::size_t i = 0; i < p1.size(); ++i) {
                    EXPECT_EQ(p4[i].light, p1[i].light);
                    EXPECT_EQ(p4[i].first, p1[i].first);
                    EXPECT_EQ(p4[i].listed, p1[i].listed);
                    EXPECT_EQ(p4[i].drawn, p1[i].drawn);
                    unlisted += p1[i].drawn - p1[i].listed;
                }
                for (std::size_t i = 0; i < s1.size(); ++i) {
                    ASSERT_EQ(bitsOf(s4[i].dir.x), bitsOf(s1[i].dir.x)) << samples << " samples";
                    ASSERT_EQ(bitsOf(s4[i].dir.y), bitsOf(s1[i].dir.y));
                    ASSERT_EQ(bitsOf(s4[i].dir.z), bitsOf(s1[i].dir.z));
                    ASSERT_EQ(bitsOf(s4[i].dist), bitsOf(s1[i].dist));
                    ASSERT_EQ(bitsOf(s4[i].nl), bitsOf(s1[i].nl));
                }
                compared += s1.size();
            }
        }
    }
    // Enough samples were compared, and some were dropped below the horizon on the way.
    EXPECT_GT(compared, 100000u);
    EXPECT_GT(unlisted, 1000u);
}

/// Random Lambert + Phong terms: some without a highlight, some with a cutoff.
SurfaceTerms<float> randomSurface(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    CompiledMaterial m{};
    m.color = Color(u(rng), u(rng), u(rng));
    m.diffuse = u(rng);
    m.specular = rng() % 3 == 0 ? 0.0f : u(rng);
    m.shininess = 1.0f + 200.0f * u(rng);
    m.specularCutoff = rng() % 2 == 0 ? 0.0f : 0.5f * u(rng);
    return surfaceTerms(m);
}

TEST(LightSamplerLanes, CentreLightsOfFourPointsHaveTheBitsOfOnePointAtATime) {
    // The level batches' path (sampleCentres + addCentreLight, four points a lane group)
    // against the one-point path (sampleLight + spanShare) on random points, normals, viewers,
    // materials and shadow flags; a lane taken from the wrong point or light fails here.
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::size_t compared = 0, listedCount = 0, blockedCount = 0, highlights = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const SceneDocument doc = lightsScene(rng, 1 + int(rng() % 16));
        const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
        const LightSampler sampler(scene);
        const std::size_t n = 1 + rng() % 61;  // whole lane groups and partial ones
        ShadingPoints points;
        points.resize(n);
        SurfaceArrays surface;
        surface.resize(n);
        std::vector<SurfaceTerms<float>> terms;
        for (std::size_t j = 0; j < n; ++j) {
            Vec3 p(u(rng), u(rng), u(rng));
            if (j % 17 == 5) p = scene.lights()[0].position;  // at the light: not listed
            const Vec3 normal =
                glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0.0f, 1e-3f, 0.0f));
            const Vec3 view =
                glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3f, 0.0f, 0.0f));
            points.set(j, p, normal, view);
            terms.push_back(randomSurface(rng));
            surface.set(j, terms.back());
        }
        std::vector<uint8_t> blocked(points.px.size());
        for (std::size_t j = 0; j < n; ++j) blocked[j] = rng() % 3 == 0;
        // Every light, each sampled at its centre (area false), lanes from a group boundary.
        for (const bool withShadows : {true, false}) {
            LightSums sums;
            sums.zero(n);
            std::vector<Color> expected(n, Color(0.0f));
            for (std::size_t li = 0; li < scene.lights().size(); ++li) {
                ASSERT_TRUE(sampler.centreOnly(li, false));
                CentreSamples centres;
                sampler.sampleCentres(li, points, 0, n, centres);
                addCentreLight(scene.lights()[li], points, surface, centres,
                               withShadows ? blocked.data() : nullptr, 0, n, sums);
                for (std::size_t j = 0; j < n; ++j) {
                    const Vec3 p(points.px[j], points.py[j], points.pz[j]);
                    const Vec3 normal(points.nx[j], points.ny[j], points.nz[j]);
                    const Vec3 view(points.vx[j], points.vy[j], points.vz[j]);
                    LightSamples samples;
                    LightSpans spans;
                    sampler.sampleLight(li, p, normal, 0u, false, samples, spans);
                    ASSERT_EQ(centres.listed[j], spans.empty() ? 0 : 1) << "point " << j;
                    if (spans.empty()) continue;
                    ASSERT_EQ(bitsOf(centres.dx[j]), bitsOf(samples[0].dir.x)) << "point " << j;
                    ASSERT_EQ(bitsOf(centres.dy[j]), bitsOf(samples[0].dir.y));
                    ASSERT_EQ(bitsOf(centres.dz[j]), bitsOf(samples[0].dir.z));
                    ASSERT_EQ(bitsOf(centres.dist[j]), bitsOf(samples[0].dist));
                    ASSERT_EQ(bitsOf(centres.nl[j]), bitsOf(samples[0].nl));
                    const uint8_t occluded = blocked[j];
                    const Color share =
                        spanShare(scene, terms[j], normal, view, spans[0], samples.data(),
                                  withShadows ? &occluded : nullptr);
                    if (share.x > terms[j].r * samples[0].nl * scene.lights()[li].power.x * 1.0001f)
                        ++highlights;
                    expected[j] += share;
                    ++listedCount;
                    blockedCount += withShadows && occluded;
                }
            }
            for (std::size_t j = 0; j < n; ++j) {
                ASSERT_EQ(bitsOf(sums.r[j]), bitsOf(expected[j].x)) << "point " << j << " of " << n;
                ASSERT_EQ(bitsOf(sums.g[j]), bitsOf(expected[j].y)) << "point " << j;
                ASSERT_EQ(bitsOf(sums.b[j]), bitsOf(expected[j].z)) << "point " << j;
                ++compared;
            }
        }
    }
    // Points were lit, shadowed and highlighted, not only dark.
    EXPECT_GT(compared, 1000u);
    EXPECT_GT(listedCount, 1000u);
    EXPECT_GT(blockedCount, 200u);
    EXPECT_GT(highlights, 50u);
}

TEST(LightSamplerLanes, SphereLightSamplesLieOnTheLightsDisk) {
    // The lanes are not merely equal to the single samples but right: every listed sample
    // points at a point within the light's radius of its centre.
    std::mt19937 rng(8);
    const SceneDocument doc = lightsScene(rng, 16);
    const CompiledScene scene(doc, nullptr, EngineKind::Builtin);
    const LightSampler sampler(scene);
    LightSamples samples;
    LightSpans spans;
    const Vec3 p(0.0f, -2.9f, 0.0f), n(0.0f, 1.0f, 0.0f);
    sampler.sample(p, n, 1234u, true, samples, spans);
    ASSERT_FALSE(spans.empty());
    for (const LightSpan& span : spans) {
        const CompiledLight& light = scene.lights()[span.light];
        EXPECT_EQ(span.drawn, light.radius > 0.0f ? 16u : 1u);
        for (uint32_t i = span.first; i < span.first + span.listed; ++i) {
            const Vec3 q = p + samples[i].dir * samples[i].dist;
            EXPECT_LE(glm::length(q - light.position), light.radius * 1.001f + 1e-5f);
            EXPECT_GT(samples[i].nl, 0.0f);
        }
    }
}

TEST(TraceKernelLanes, ABatchOfCameraRaysHasTheBitsOfEachRayAlone) {
    // The kernel shades a level's points four at a time; a camera ray traced alone fills one
    // lane of one group. Every pixel of a batch must have the bits of its ray alone, for
    // every shadow mode and the policies' diffuse mirrors and glass, with two point lights and
    // a sphere light (lights in scene order, some sampled per point, some per lane group).
    SceneDocument doc = test::smallRoom(24, 18);
    doc.render.shadowSamples = 4;
    test::addPointLight(doc, "fill", Vec3(-3, 1, -1));
    test::addSphereLight(doc, "sphere", Vec3(2, 2.5f, -4));
    for (EngineKind engine : {EngineKind::Embree, EngineKind::Builtin}) {
        const CompiledScene scene(doc, nullptr, engine);
        const test::PixelRays pixels(scene, doc.render.width, doc.render.height);
        const std::size_t n = pixels.size();
        std::vector<TraceOptions> optionSets(5, TraceOptions::fromSettings(doc.render));
        optionSets[1].shadows = ShadowQuality::HardOnly;
        optionSets[2].shadows = ShadowQuality::Off;
        optionSets[3].shadows = ShadowQuality::Deferred;
        optionSets[4].reflectionAsDiffuse = optionSets[4].refractionAsDiffuse = true;
        for (std::size_t o = 0; o < optionSets.size(); ++o) {
            const TraceKernel kernel(scene, optionSets[o]);
            std::vector<Color> batch(n), alone(n);
            std::vector<uint32_t> batchRays(n), aloneRays(n);
            TraceCounters counters;
            TraceOutput out;
            out.color = batch.data();
            out.rays = batchRays.data();
            ASSERT_TRUE(kernel.trace(pixels.batch(), out, counters));
            std::size_t lit = 0;
            for (std::size_t i = 0; i < n; ++i) {
                TraceOutput one;
                one.color = &alone[i];
                one.rays = &aloneRays[i];
                kernel.trace(pixels.one(i), one, counters);
                ASSERT_EQ(bitsOf(batch[i].x), bitsOf(alone[i].x))
                    << "pixel " << i << " options " << o;
                ASSERT_EQ(bitsOf(batch[i].y), bitsOf(alone[i].y))
                    << "pixel " << i << " options " << o;
                ASSERT_EQ(bitsOf(batch[i].z), bitsOf(alone[i].z))
                    << "pixel " << i << " options " << o;
                ASSERT_EQ(batchRays[i], aloneRays[i]) << "pixel " << i << " options " << o;
                lit += batch[i].x > 0.2f;
            }
            EXPECT_GT(lit, n / 10) << "options " << o;  // not a dark image
        }
    }
}

}  // namespace
}  // namespace rs
