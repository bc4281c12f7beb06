// Image files: write/read round trips per format, tone mapping on 8-bit output, error messages.
#include "image/image_io.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "image/tonemap.h"

namespace rs {

namespace {

namespace fs = std::filesystem;

/// A fresh, empty folder per test, removed afterwards.
class ImageIo : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("raystudio-image-io-" + std::string(info->name()) +
                                            "-" + std::to_string(std::random_device{}()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    /// Everything in the folder, to prove no temporary file was left behind.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_))
            names.push_back(entry.path().filename().string());
        return names;
    }

    fs::path dir_;
};

/// A small image with a gradient, saturated colours and values above 1.
ImageRgb hdrTestImage() {
    ImageRgb img(7, 5);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            img.at(x, y) =
                Color(0.37f * float(x), 0.11f * float(y) + 0.001f, float(x * y) / 9.0f + 0.25f);
    img.at(0, 0) = Color(0.0f);
    img.at(6, 4) = Color(123.456f, 0.0001234f, 7.5f);
    return img;
}

/// Values inside [0, 1], so Clamp leaves them alone and 8-bit files can round-trip them.
ImageRgb ldrTestImage() {
    ImageRgb img(16, 4);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            img.at(x, y) =
                Color(float(x) / 15.0f, float(y) / 3.0f, float((x * 7 + y) % 16) / 15.0f);
    return img;
}

/// Compares two images in encoded (display) space, where 8-bit quantisation is uniform.
void expectEncodedNear(const ImageRgb& actual, const ImageRgb& expected, float tol) {
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    for (std::size_t i = 0; i < expected.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(srgbEncode(actual.pixels[i][c]), srgbEncode(expected.pixels[i][c]), tol)
                << "pixel " << i << " channel " << c;
}

void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace

TEST_F(ImageIo, Exr_RoundTripsFloatsExactly) {
    const ImageRgb img = hdrTestImage();
    std::string error;
    ASSERT_TRUE(writeImage(path("out.exr"), img, ToneMap::Aces, 3.0f, error)) << error;
    ImageRgb back;
    ASSERT_TRUE(readImage(path("out.exr"), back, error)) << error;
    ASSERT_EQ(back.width, img.width);
    ASSERT_EQ(back.height, img.height);
    // Linear output: neither the operator nor the exposure touches the stored radiance.
    EXPECT_EQ(back.pixels, img.pixels);
}

TEST_F(ImageIo, Hdr_RoundTripsWithinRgbePrecision) {
    const ImageRgb img = hdrTestImage();
    std::string error;
    ASSERT_TRUE(writeImage(path("out.hdr"), img, ToneMap::Clamp, 0.0f, error)) << error;
    ImageRgb back;
    ASSERT_TRUE(readImage(path("out.hdr"), back, error)) << error;
    ASSERT_EQ(back.width, img.width);
    ASSERT_EQ(back.height, img.height);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) {
        // RGBE shares one exponent per pixel: error is relative to the brightest channel.
        const Color& a = img.pixels[i];
        const float largest = std::max({a.x, a.y, a.z});
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back.pixels[i][c], a[c], largest / 128.0f + 1e-6f) << "pixel " << i;
    }
    EXPECT_GT(back.at(6, 4).x, 100.0f);  // stored linear, not tone-mapped
}

TEST_F(ImageIo, Png_RoundTripsWithinOneStepOf255AfterEncoding) {
    const ImageRgb img = ldrTestImage();
    std::string error;
    ASSERT_TRUE(writeImage(path("out.png"), img, ToneMap::Clamp, 0.0f, error)) << error;
    ImageRgb back;
    ASSERT_TRUE(readImage(path("out.png"), back, error)) << error;
    expectEncodedNear(back, img, 0.5f / 255.0f + 1e-5f);
}

TEST_F(ImageIo, Tiff_RoundTripsWithinOneStepOf255AfterEncoding) {
    const ImageRgb img = ldrTestImage();
    std::string error;
    for (const char* name : {"out.tif", "out.TIFF"}) {
        ASSERT_TRUE(writeImage(path(name), img, ToneMap::Clamp, 0.0f, error)) << error;
        ImageRgb back;
        ASSERT_TRUE(readImage(path(name), back, error)) << error;
        expectEncodedNear(back, img, 0.5f / 255.0f + 1e-5f);
    }
}

TEST_F(ImageIo, Jpeg_RoundTripsAFlatColourClosely) {
    // JPEG is lossy; a flat colour survives its block transform almost exactly.
    ImageRgb img(16, 16);
    for (Color& c : img.pixels) c = Color(0.6f, 0.3f, 0.1f);
    std::string error;
    for (const char* name : {"out.jpg", "out.jpeg"}) {
        ASSERT_TRUE(writeImage(path(name), img, ToneMap::Clamp, 0.0f, error)) << error;
        ImageRgb back;
        ASSERT_TRUE(readImage(path(name), back, error)) << error;
        expectEncodedNear(back, img, 3.0f / 255.0f);
    }
}

TEST_F(ImageIo, Png_IsToneMappedWithOperatorAndExposure) {
    ImageRgb img(2, 1);
    img.at(0, 0) = Color(3.0f);  // Reinhard: 3 / 4
    img.at(1, 0) = Color(0.5f);  // exposure +1 stop first: 1 / 2
    std::string error;
    ASSERT_TRUE(writeImage(path("out.png"), img, ToneMap::Reinhard, 1.0f, error)) << error;
    ImageRgb back;
    ASSERT_TRUE(readImage(path("out.png"), back, error)) << error;
    EXPECT_NEAR(srgbEncode(back.at(0, 0).x), srgbEncode(6.0f / 7.0f), 0.5f / 255.0f + 1e-5f);
    EXPECT_NEAR(srgbEncode(back.at(1, 0).y), srgbEncode(0.5f), 0.5f / 255.0f + 1e-5f);
}

TEST_F(ImageIo, Write_ReplacesAnExistingFileAndLeavesNoTemporaryFiles) {
    std::string error;
    ASSERT_TRUE(writeImage(path("out.png"), ldrTestImage(), ToneMap::Clamp, 0.0f, error)) << error;
    ImageRgb small(3, 2);
    ASSERT_TRUE(writeImage(path("out.png"), small, ToneMap::Clamp, 0.0f, error)) << error;
    ImageRgb back;
    ASSERT_TRUE(readImage(path("out.png"), back, error)) << error;
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(listing(), std::vector<std::string>{"out.png"});
}

TEST_F(ImageIo, UnknownExtension_FailsNamingPathAndSupportedExtensions) {
    std::string error;
    EXPECT_FALSE(writeImage(path("out.bmp"), ldrTestImage(), ToneMap::Clamp, 0.0f, error));
    EXPECT_NE(error.find(path("out.bmp")), std::string::npos) << error;
    EXPECT_NE(error.find(".bmp"), std::string::npos) << error;
    for (const char* ext : {".png", ".jpg", ".tif", ".exr", ".hdr"})
        EXPECT_NE(error.find(ext), std::string::npos) << error;
    EXPECT_TRUE(listing().empty());

    error.clear();
    EXPECT_FALSE(writeImage(path("no-extension"), ldrTestImage(), ToneMap::Clamp, 0.0f, error));
    EXPECT_NE(error.find(path("no-extension")), std::string::npos) << error;
}

TEST_F(ImageIo, UnwritablePath_FailsNamingThePath) {
    // A regular file where a folder should be: fails even for root, unlike permission bits.
    writeBytes(path("not-a-folder"), {1, 2, 3});
    const std::string target = path("not-a-folder/out.png");
    std::string error;
    EXPECT_FALSE(writeImage(target, ldrTestImage(), ToneMap::Clamp, 0.0f, error));
    EXPECT_NE(error.find(target), std::string::npos) << error;
}

TEST_F(ImageIo, FailedRename_LeavesNoTemporaryFileBehind) {
    // A folder in the way of the final rename: the image is written, then cannot be moved.
    fs::create_directory(path("out.exr"));
    std::string error;
    EXPECT_FALSE(writeImage(path("out.exr"), hdrTestImage(), ToneMap::Clamp, 0.0f, error));
    EXPECT_NE(error.find(path("out.exr")), std::string::npos) << error;
    EXPECT_EQ(listing(), std::vector<std::string>{"out.exr"});
    EXPECT_TRUE(fs::is_directory(path("out.exr")));
}

TEST_F(ImageIo, EmptyImage_IsRefused) {
    std::string error;
    EXPECT_FALSE(writeImage(path("out.png"), ImageRgb(), ToneMap::Clamp, 0.0f, error));
    EXPECT_NE(error.find(path("out.png")), std::string::npos) << error;
    EXPECT_TRUE(listing().empty());
}

TEST_F(ImageIo, Read_MissingFileFailsNamingThePath) {
    ImageRgb img;
    std::string error;
    EXPECT_FALSE(readImage(path("missing.png"), img, error));
    EXPECT_NE(error.find(path("missing.png")), std::string::npos) << error;
}

TEST_F(ImageIo, Read_GreyIsReplicatedAndDecoded) {
    // Binary PGM, 2x1, grey levels 0 and 128.
    writeBytes(path("grey.pgm"),
               {'P', '5', '\n', '2', ' ', '1', '\n', '2', '5', '5', '\n', 0, 128});
    ImageRgb img;
    std::string error;
    ASSERT_TRUE(readImage(path("grey.pgm"), img, error)) << error;
    ASSERT_EQ(img.width, 2);
    ASSERT_EQ(img.height, 1);
    EXPECT_EQ(img.at(0, 0), Color(0.0f));
    const float expected = srgbDecode(128.0f / 255.0f);
    EXPECT_NEAR(img.at(1, 0).x, expected, 1e-6f);
    EXPECT_NEAR(img.at(1, 0).y, expected, 1e-6f);
    EXPECT_NEAR(img.at(1, 0).z, expected, 1e-6f);
}

TEST_F(ImageIo, Read_AlphaIsDroppedWithoutPremultiplying) {
    // Uncompressed 32-bit TGA, 1x1, top-left origin; BGRA = (50, 100, 200, alpha 64).
    std::vector<uint8_t> tga = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 32, 0x28};
    tga.insert(tga.end(), {50, 100, 200, 64});
    writeBytes(path("rgba.tga"), tga);
    ImageRgb img;
    std::string error;
    ASSERT_TRUE(readImage(path("rgba.tga"), img, error)) << error;
    EXPECT_NEAR(img.at(0, 0).x, srgbDecode(200.0f / 255.0f), 1e-6f);
    EXPECT_NEAR(img.at(0, 0).y, srgbDecode(100.0f / 255.0f), 1e-6f);
    EXPECT_NEAR(img.at(0, 0).z, srgbDecode(50.0f / 255.0f), 1e-6f);
}

}  // namespace rs
