// TextureStore: sRGB and linear files, wrap, MIP means, bad files, environments, threads.
// Every image is written here, into a fresh temporary folder, with OpenImageIO's ImageOutput.
#include "texture/texture_store.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>
#include <vector>

#include "texture/texel_cache.h"

namespace rs {
namespace {

namespace fs = std::filesystem;
using OIIO::TypeDesc;

/// The sRGB EOTF written out here, in double, independently of the product's table.
double srgbDecode(double code, double maxCode) {
    const double c = code / maxCode;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

void expectColor(const Color& got, double r, double g, double b, double relative,
                 double absolute = 1e-6) {
    EXPECT_NEAR(got.x, r, relative * std::abs(r) + absolute);
    EXPECT_NEAR(got.y, g, relative * std::abs(g) + absolute);
    EXPECT_NEAR(got.z, b, relative * std::abs(b) + absolute);
}

class TextureStoreTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "raystudio-texture-XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    /// Writes a w x h image of `channels` channels of `format` from `pixels` (top row first).
    std::string write(const std::string& name, int w, int h, int channels, TypeDesc format,
                      const void* pixels, const char* compression = nullptr) {
        const std::string file = path(name);
        auto out = OIIO::ImageOutput::create(file);
        EXPECT_TRUE(out) << OIIO::geterror();
        if (!out) return file;
        OIIO::ImageSpec spec(w, h, channels, format);
        if (compression) spec.attribute("compression", compression);
        EXPECT_TRUE(out->open(file, spec)) << out->geterror();
        EXPECT_TRUE(out->write_image(format, pixels)) << out->geterror();
        EXPECT_TRUE(out->close());
        return file;
    }

    TextureHandle open(const std::string& file) {
        std::string error;
        TextureHandle h = TextureStore::shared().open(file, error);
        EXPECT_TRUE(h) << error;
        EXPECT_TRUE(error.empty());
        return h;
    }

    static Color at(const TextureHandle& h, float s, float t) {
        return TextureStore::shared().lookup(h, s, t, 0, 0, 0, 0);
    }

    fs::path dir_;
};

TEST_F(TextureStoreTest, EightBitPngIsSrgbDecodedAtTexelCentres) {
    const std::uint8_t codes[2][2][3] = {{{255, 0, 0}, {0, 128, 255}},
                                         {{64, 64, 64}, {200, 100, 10}}};
    const TextureHandle h = open(write("four.png", 2, 2, 3, TypeDesc::UINT8, codes));
    EXPECT_TRUE(h.srgb);
    EXPECT_EQ(h.channels, 3);
    for (int row = 0; row < 2; ++row) {
        for (int col = 0; col < 2; ++col) {
            const auto& c = codes[row][col];
            // Row 0 is the top: t = 0.25.
            expectColor(at(h, (col + 0.5f) / 2, (row + 0.5f) / 2), srgbDecode(c[0], 255),
                        srgbDecode(c[1], 255), srgbDecode(c[2], 255), 1e-3, 1e-5);
        }
    }
}

TEST_F(TextureStoreTest, SixteenBitPngIsSrgbDecodedToo) {
    const std::uint16_t codes[1][2][3] = {{{1000, 40000, 65535}, {20000, 0, 5000}}};
    const TextureHandle h = open(write("deep.png", 2, 1, 3, TypeDesc::UINT16, codes));
    EXPECT_TRUE(h.srgb);
    for (int col = 0; col < 2; ++col) {
        const auto& c = codes[0][col];
        expectColor(at(h, (col + 0.5f) / 2, 0.5f), srgbDecode(c[0], 65535), srgbDecode(c[1], 65535),
                    srgbDecode(c[2], 65535), 1e-3, 1e-6);
    }
}

TEST_F(TextureStoreTest, FloatExrIsLinearAsStored) {
    const float values[2][2][3] = {{{0.25f, 5.0f, 0.0f}, {1.0f, 0.5f, 0.125f}},
                                   {{0.01f, 0.02f, 0.03f}, {100.0f, 0.75f, 2.5f}}};
    const TextureHandle h = open(write("linear.exr", 2, 2, 3, TypeDesc::FLOAT, values));
    EXPECT_FALSE(h.srgb);
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 2; ++col) {
            const auto& v = values[row][col];
            expectColor(at(h, (col + 0.5f) / 2, (row + 0.5f) / 2), v[0], v[1], v[2], 1e-6);
        }
}

TEST_F(TextureStoreTest, GreyImagesAreGreyAndAlphaIsIgnored) {
    const std::uint8_t grey[1][2] = {{50, 220}};
    const TextureHandle g = open(write("grey.png", 2, 1, 1, TypeDesc::UINT8, grey));
    EXPECT_EQ(g.channels, 1);
    const double g0 = srgbDecode(50, 255), g1 = srgbDecode(220, 255);
    expectColor(at(g, 0.25f, 0.5f), g0, g0, g0, 1e-3, 1e-5);
    expectColor(at(g, 0.75f, 0.5f), g1, g1, g1, 1e-3, 1e-5);
    // A fully transparent red texel is still red (not premultiplied to black).
    const std::uint8_t rgba[1][1][4] = {{{255, 128, 0, 0}}};
    const TextureHandle a = open(write("clear.png", 1, 1, 4, TypeDesc::UINT8, rgba));
    EXPECT_EQ(a.channels, 4);
    expectColor(at(a, 0.5f, 0.5f), 1.0, srgbDecode(128, 255), 0.0, 1e-3, 1e-5);
}

TEST_F(TextureStoreTest, CoordinatesWrapPeriodically) {
    const float values[2][2][3] = {{{1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {1, 1, 1}}};
    const TextureHandle h = open(write("wrap.exr", 2, 2, 3, TypeDesc::FLOAT, values));
    for (float s : {0.25f, 0.75f, 0.1f})
        for (float t : {0.25f, 0.75f, 0.6f}) {
            const Color base = at(h, s, t);
            for (float k : {-3.0f, -1.0f, 1.0f, 2.0f}) {
                const Color moved = at(h, s + k, t - k);
                expectColor(moved, base.x, base.y, base.z, 1e-4, 1e-5);
            }
        }
    // Halfway between the last and the first column (s = 0) blends them, as across any edge.
    expectColor(at(h, 0.0f, 0.25f), 0.5, 0.5, 0.0, 1e-5, 1e-6);
    // And the bottom row with the top one (t = 0).
    expectColor(at(h, 0.25f, 0.0f), 0.5, 0.0, 0.5, 1e-5, 1e-6);
}

TEST_F(TextureStoreTest, LargeFootprintGivesTheMeanOfLinearValues) {
    // Float: the mean of arbitrary values.
    std::vector<float> values(16 * 16 * 3);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> uniform(0.0f, 4.0f);
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < values.size(); ++i) {
        values[i] = uniform(random);
        sum[i % 3] += values[i];
    }
    const TextureHandle f = open(write("noise.exr", 16, 16, 3, TypeDesc::FLOAT, values.data()));
    const Color mean = TextureStore::shared().lookup(f, 0.3f, 0.6f, 4.0f, 0.0f, 0.0f, 4.0f);
    expectColor(mean, sum[0] / 256, sum[1] / 256, sum[2] / 256, 1e-4);
    // 8-bit black and white checks: linear mean 0.5, not the 0.21 of decoding a filtered code.
    std::vector<std::uint8_t> checks(16 * 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) checks[y * 16 + x] = ((x + y) % 2) ? 255 : 0;
    const TextureHandle c = open(write("checks.png", 16, 16, 1, TypeDesc::UINT8, checks.data()));
    const Color grey = TextureStore::shared().lookup(c, 0.3f, 0.6f, 4.0f, 0.0f, 0.0f, 4.0f);
    expectColor(grey, 0.5, 0.5, 0.5, 2e-3);
    // One level down (a footprint of two texels) already averages pairs: still 0.5.
    const Color pairs = TextureStore::shared().lookup(c, 0.5f, 0.5f, 2.0f / 16, 0, 0, 2.0f / 16);
    expectColor(pairs, 0.5, 0.5, 0.5, 0.02);
}

TEST_F(TextureStoreTest, BadFilesGiveEmptyHandlesAndNameTheFile) {
    std::string error;
    auto& store = TextureStore::shared();
    const std::string missing = path("nowhere.png");
    EXPECT_FALSE(store.open(missing, error));
    EXPECT_NE(error.find(missing), std::string::npos) << error;
    EXPECT_NE(error.find("No such file"), std::string::npos) << error;

    const std::string folder = path("folder.png");
    fs::create_directory(folder);
    EXPECT_FALSE(store.open(folder, error));
    EXPECT_NE(error.find(folder), std::string::npos) << error;
    EXPECT_NE(error.find("directory"), std::string::npos) << error;

    const std::string corrupt = path("noise.png");
    {
        std::ofstream out(corrupt, std::ios::binary);
        std::mt19937 random(3);
        for (int i = 0; i < 4096; ++i) out.put(char(random() & 0xff));
    }
    EXPECT_FALSE(store.open(corrupt, error));
    EXPECT_NE(error.find(corrupt), std::string::npos) << error;

    const std::string empty = path("empty.exr");
    std::ofstream(empty).close();
    EXPECT_FALSE(store.open(empty, error));
    EXPECT_NE(error.find(empty), std::string::npos) << error;

    // An empty handle looks up the "missing" pattern.
    const Color m = store.lookup(TextureHandle{}, 0.01f, 0.01f, 0, 0, 0, 0);
    expectColor(m, 1.0, 0.0, 1.0, 0.0);
}

TEST_F(TextureStoreTest, PlainImagesOverTheAutoMipLimitAreRefusedWithAWayOut) {
    // 4097 x 4097 grey, compressed to almost nothing on disk: just over kMaxAutoMipPixels.
    std::vector<std::uint8_t> pixels(size_t(4097) * 4097, 128);
    const std::string file =
        write("huge.tif", 4097, 4097, 1, TypeDesc::UINT8, pixels.data(), "zip");
    std::string error;
    EXPECT_FALSE(TextureStore::shared().open(file, error));
    EXPECT_NE(error.find(file), std::string::npos) << error;
    EXPECT_NE(error.find("4097 x 4097"), std::string::npos) << error;
    EXPECT_NE(error.find("maketx"), std::string::npos) << error;
}

TEST_F(TextureStoreTest, EnvironmentFollowsTheSphericalMapAndTurns) {
    // 64 x 32 lat-long: a sky band on top, a ground band below, and between them four
    // regions centred on +X, +Z, -X, -Z (u = 0, 0.25, 0.5, 0.75), the first across the seam.
    const float sky[3] = {0.2f, 0.4f, 0.9f}, ground[3] = {0.3f, 0.2f, 0.1f};
    const float region[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    std::vector<float> pixels(64 * 32 * 3);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            const float* c = y < 8 ? sky : y >= 24 ? ground : region[((x + 8) / 16) % 4];
            for (int k = 0; k < 3; ++k) pixels[(y * 64 + x) * 3 + k] = c[k];
        }
    const TextureHandle h = open(write("latlong.exr", 64, 32, 3, TypeDesc::FLOAT, pixels.data()));
    auto& store = TextureStore::shared();
    const float cone = 0.01f;
    auto expectIs = [&](const Vec3& d, float rotation, const float* c) {
        const Color got = store.environment(h, d, rotation, cone);
        expectColor(got, c[0], c[1], c[2], 1e-4, 1e-5);
    };
    expectIs(Vec3(0, 1, 0), 0, sky);
    expectIs(Vec3(0, -1, 0), 0, ground);
    expectIs(Vec3(0.01f, 1, 0.02f), 0, sky);
    expectIs(Vec3(1, 0, 0), 0, region[0]);
    expectIs(Vec3(0, 0, 1), 0, region[1]);
    expectIs(Vec3(-1, 0, 0), 0, region[2]);
    expectIs(Vec3(0, 0, -1), 0, region[3]);
    expectIs(Vec3(3, 0, 0), 0, region[0]);  // directions need not be unit
    // Turned 90 degrees about +Y: what was at +Z is now toward +X, and so on round.
    expectIs(Vec3(1, 0, 0), 90, region[1]);
    expectIs(Vec3(0, 0, 1), 90, region[2]);
    expectIs(Vec3(0, 0, -1), 90, region[0]);
    expectIs(Vec3(1, 0, 0), -90, region[3]);
    expectIs(Vec3(1, 0, 0), 360, region[0]);
    expectIs(Vec3(0, 1, 0), 90, sky);
    // A cone as wide as the region (1.2 rad: 0.19 in s, 0.38 in t) still sees only it; a
    // wider one blends in its neighbours, and a wide cone at the pole sees the sky band.
    const Color inside = store.environment(h, Vec3(1, 0, 0), 0, 1.2f);
    expectColor(inside, region[0][0], region[0][1], region[0][2], 0.02, 0.02);
    const Color wide = store.environment(h, Vec3(1, 0, 0), 0, 2.5f);
    EXPECT_GT(std::abs(wide.x - 1.0f) + std::abs(wide.y) + std::abs(wide.z), 0.05f);
    expectColor(store.environment(h, Vec3(0, 1, 0), 0, 0.3f), sky[0], sky[1], sky[2], 1e-3);
    // An empty handle shows the missing pattern.
    const Color m = store.environment(TextureHandle{}, Vec3(1, 0, 0), 0, cone);
    EXPECT_TRUE(m == Color(1, 0, 1) || m == Color(0));
}

TEST_F(TextureStoreTest, FileChangedOnDiskIsReadAfresh) {
    const std::uint8_t red[1][1][3] = {{{255, 0, 0}}};
    const std::string file = write("changing.png", 1, 1, 3, TypeDesc::UINT8, red);
    const TextureHandle first = open(file);
    expectColor(at(first, 0.5f, 0.5f), 1.0, 0.0, 0.0, 1e-3, 1e-5);
    const std::uint8_t blue[1][1][3] = {{{0, 0, 255}}};
    write("changing.png", 1, 1, 3, TypeDesc::UINT8, blue);
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(5));
    const TextureHandle second = open(file);
    expectColor(at(second, 0.5f, 0.5f), 0.0, 0.0, 1.0, 1e-3, 1e-5);
}

TEST_F(TextureStoreTest, FileSavedAgainAndAgain_KeepsOnlyTheVersionsStillHeld) {
    // A paint program saving the same texture over and over: each version's whole levels go
    // back to the resident budget once no handle holds that version, so the tenth version
    // is kept whole as the first was (lookups stay on the fast path).
    std::vector<std::uint8_t> texels(64 * 64 * 3);
    const auto save = [&](int version) {
        for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint8_t(i * 7 + version);
        const std::string file = write("painted.png", 64, 64, 3, TypeDesc::UINT8, texels.data());
        fs::last_write_time(file, fs::file_time_type::clock::now() + std::chrono::seconds(version));
        return file;
    };
    const std::size_t before = residentTexelBytes();
    std::size_t one = 0;
    {
        const TextureHandle first = open(save(1));
        at(first, 0.5f, 0.5f);  // level 0 kept whole
        one = residentTexelBytes() - before;
        ASSERT_GT(one, 64u * 64u * 4u);
        TextureHandle held = first;
        for (int version = 2; version <= 10; ++version) {
            const TextureHandle next = open(save(version));
            ASSERT_NE(next.texels, held.texels) << version;
            at(next, 0.5f, 0.5f);
            held = next;  // the version before is held by nobody now but `first`'s
        }
        // `first` (still held) and the tenth, which the store holds as the file's latest.
        EXPECT_EQ(residentTexelBytes() - before, 2 * one);
    }
    EXPECT_EQ(residentTexelBytes() - before, one);
}

TEST_F(TextureStoreTest, LookupsFromManyThreadsAgreeWithOneThread) {
    std::vector<float> values(32 * 32 * 3);
    for (size_t i = 0; i < values.size(); ++i) values[i] = float((i * 37) % 101) / 100.0f;
    const TextureHandle h = open(write("threads.exr", 32, 32, 3, TypeDesc::FLOAT, values.data()));
    auto sample = [&](int i) {
        const float s = 0.013f * i, t = 0.007f * i, d = 0.001f * (i % 50);
        return TextureStore::shared().lookup(h, s, t, d, 0, 0, d);
    };
    std::vector<Color> serial(2000);
    for (int i = 0; i < 2000; ++i) serial[i] = sample(i);
    std::vector<std::thread> threads;
    std::vector<int> mismatches(4, 0);
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
            for (int i = 0; i < 2000; ++i)
                if (sample((i + 500 * k) % 2000) != serial[(i + 500 * k) % 2000]) ++mismatches[k];
        });
    for (auto& t : threads) t.join();
    for (int k = 0; k < 4; ++k) EXPECT_EQ(mismatches[k], 0);
}

TEST(TextureStoreCache, MegabytesAreSetAndReadBack) {
    auto& store = TextureStore::shared();
    const float before = store.cacheMegabytes();
    EXPECT_GT(before, 0.0f);
    store.setCacheMegabytes(64.0f);
    EXPECT_EQ(store.cacheMegabytes(), 64.0f);
    store.setCacheMegabytes(-5.0f);  // ignored
    EXPECT_EQ(store.cacheMegabytes(), 64.0f);
    store.setCacheMegabytes(before);
}

TEST(MissingTexture, MagentaAndBlackChecksEightPerUnit) {
    EXPECT_EQ(missingTexture(0.01f, 0.01f), Color(1, 0, 1));
    EXPECT_EQ(missingTexture(0.13f, 0.01f), Color(0));
    EXPECT_EQ(missingTexture(0.13f, 0.13f), Color(1, 0, 1));
    EXPECT_EQ(missingTexture(-0.01f, 0.01f), Color(0));
    EXPECT_EQ(missingTexture(1.01f, 0.01f), Color(1, 0, 1));
}

}  // namespace
}  // namespace rs
