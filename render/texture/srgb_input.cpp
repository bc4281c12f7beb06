// The sRGB-to-linear reader: the wrapped file read as 16-bit integers, decoded through a table.
#include "texture/srgb_input.h"

#include <OpenImageIO/half.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace rs {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

bool isSrgbEncoded(OIIO::TypeDesc format) {
    switch (format.basetype) {
        case OIIO::TypeDesc::UINT8:
        case OIIO::TypeDesc::INT8:
        case OIIO::TypeDesc::UINT16:
        case OIIO::TypeDesc::INT16:
            return true;
        default:
            return false;
    }
}

namespace {

/// Linear half for every 16-bit code (8-bit files arrive as code * 257, exactly k / 255).
/// Computed in double so the table holds the correctly rounded half of the exact EOTF.
const half* decodeTable() {
    static const std::unique_ptr<half[]> table = [] {
        std::unique_ptr<half[]> t(new half[65536]);
        for (int code = 0; code < 65536; ++code) {
            const double c = code / 65535.0;
            const double linear = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
            t[code] = half(float(linear));
        }
        return t;
    }();
    return table.get();
}

class SrgbLinearInput final : public OIIO::ImageInput {
public:
    const char* format_name() const override { return "srgb-linearised"; }

    bool open(const std::string& name, OIIO::ImageSpec& newspec) override {
        return open(name, newspec, OIIO::ImageSpec());
    }

    bool open(const std::string& name, OIIO::ImageSpec& newspec,
              const OIIO::ImageSpec& config) override {
        inner_ = OIIO::ImageInput::open(name, &config);
        if (!inner_) {
            errorfmt("{}", OIIO::geterror());
            return false;
        }
        adoptInnerSpec();
        newspec = m_spec;
        return true;
    }

    bool close() override {
        inner_.reset();
        return true;
    }

    int current_subimage() const override { return subimage_; }
    int current_miplevel() const override { return miplevel_; }

    bool seek_subimage(int subimage, int miplevel) override {
        if (!inner_) return false;
        if (subimage == subimage_ && miplevel == miplevel_) return true;
        if (!inner_->seek_subimage(subimage, miplevel)) return false;
        subimage_ = subimage;
        miplevel_ = miplevel;
        adoptInnerSpec();
        return true;
    }

    bool read_native_scanline(int subimage, int miplevel, int y, int z, void* data) override {
        return read_native_scanlines(subimage, miplevel, y, y + 1, z, data);
    }

    bool read_native_scanlines(int subimage, int miplevel, int ybegin, int yend, int z,
                               void* data) override {
        lock_guard lock(*this);
        if (!seek_subimage(subimage, miplevel)) return false;
        yend = std::min(yend, m_spec.y + m_spec.height);
        const size_t values =
            size_t(m_spec.width) * size_t(std::max(yend - ybegin, 0)) * size_t(m_spec.nchannels);
        std::vector<std::uint16_t> codes(values);
        if (!inner_->read_scanlines(subimage, miplevel, ybegin, yend, z, 0, m_spec.nchannels,
                                    OIIO::TypeDesc::UINT16, codes.data())) {
            errorfmt("{}", inner_->geterror());
            return false;
        }
        decode(codes, static_cast<half*>(data));
        return true;
    }

    bool read_native_tile(int subimage, int miplevel, int x, int y, int z, void* data) override {
        lock_guard lock(*this);
        if (!seek_subimage(subimage, miplevel)) return false;
        const int tw = m_spec.tile_width, th = m_spec.tile_height;
        const int td = std::max(m_spec.tile_depth, 1);
        const OIIO::stride_t pixel = OIIO::stride_t(m_spec.nchannels) * 2;
        std::vector<std::uint16_t> codes(size_t(tw) * th * td * m_spec.nchannels, 0);
        const int xend = std::min(x + tw, m_spec.x + m_spec.width);
        const int yend = std::min(y + th, m_spec.y + m_spec.height);
        const int zend = std::min(z + td, m_spec.z + std::max(m_spec.depth, 1));
        if (!inner_->read_tiles(subimage, miplevel, x, xend, y, yend, z, zend, 0, m_spec.nchannels,
                                OIIO::TypeDesc::UINT16, codes.data(), pixel, pixel * tw,
                                pixel * tw * th)) {
            errorfmt("{}", inner_->geterror());
            return false;
        }
        decode(codes, static_cast<half*>(data));
        return true;
    }

private:
    void adoptInnerSpec() {
        m_spec = inner_->spec();
        m_spec.set_format(OIIO::TypeDesc::HALF);
        m_spec.channelformats.clear();
        m_spec.attribute("oiio:ColorSpace", "Linear");
    }

    void decode(const std::vector<std::uint16_t>& codes, half* out) const {
        const half* table = decodeTable();
        const int channels = m_spec.nchannels;
        const int alpha = m_spec.alpha_channel;
        for (size_t i = 0; i < codes.size(); ++i) {
            const int channel = int(i % size_t(channels));
            out[i] = channel == alpha ? half(codes[i] / 65535.0f) : table[codes[i]];
        }
    }

    std::unique_ptr<OIIO::ImageInput> inner_;
    int subimage_ = 0, miplevel_ = 0;
};

}  // namespace

OIIO::ImageInput* createSrgbLinearInput() {
    return new SrgbLinearInput;
}

}  // namespace rs
