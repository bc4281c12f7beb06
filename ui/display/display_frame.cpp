// The GUI-side frame: its damage, and shading its views on the CPU (the raster viewport and
// tests). Copying the session's deep frame into it is the adapter's (adapter/frame_handover.cpp).
#include "display/display_frame.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>

#include "image/tonemap.h"

namespace rs::ui {

bool showsDebugBuffers(ViewMode mode) {
    return mode == ViewMode::Normals || mode == ViewMode::Cost;
}

bool DisplayFrame::changedSince(uint64_t seen, std::vector<QRect>& rects) const {
    rects.clear();
    if (seen < damageFloor) return false;
    for (const Damage& d : damage)
        if (d.serial > seen) rects.push_back(d.rect);
    return true;
}

std::vector<QRect> mergeRects(std::vector<QRect> rects, const QSize& frame) {
    if (rects.size() < 2) return rects;
    // Rows first: tiles of one tile row side by side become one band.
    std::sort(rects.begin(), rects.end(), [](const QRect& a, const QRect& b) {
        return std::make_tuple(a.top(), a.bottom(), a.left()) <
               std::make_tuple(b.top(), b.bottom(), b.left());
    });
    std::vector<QRect> rows;
    for (const QRect& r : rects) {
        if (!rows.empty() && rows.back().top() == r.top() && rows.back().bottom() == r.bottom() &&
            r.left() <= rows.back().right() + 1)
            rows.back() = rows.back().united(r);
        else
            rows.push_back(r);
    }
    // Then bands of equal span stacked on each other.
    std::sort(rows.begin(), rows.end(), [](const QRect& a, const QRect& b) {
        return std::make_tuple(a.left(), a.right(), a.top()) <
               std::make_tuple(b.left(), b.right(), b.top());
    });
    std::vector<QRect> out;
    long long area = 0;
    for (const QRect& r : rows) {
        if (!out.empty() && out.back().left() == r.left() && out.back().right() == r.right() &&
            r.top() <= out.back().bottom() + 1)
            out.back() = out.back().united(r);
        else
            out.push_back(r);
    }
    for (const QRect& r : out) area += (long long)r.width() * r.height();
    // Many scattered pieces that cover most of the frame: one copy is cheaper than many.
    if (out.size() > 64 && area * 2 > (long long)frame.width() * frame.height())
        return {QRect(QPoint(0, 0), frame)};
    return out;
}

void idColor(ObjectId id, uint8_t rgb[3]) {
    if (id == kNoObject) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return;
    }
    uint32_t h = id * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    rgb[0] = uint8_t(64 + (h & 0xBF));
    rgb[1] = uint8_t(64 + ((h >> 8) & 0xBF));
    rgb[2] = uint8_t(64 + ((h >> 16) & 0xBF));
}

namespace {

/// Blue-to-red heat ramp for t in [0, 1].
void heat(float t, uint8_t rgb[3]) {
    t = std::clamp(t, 0.0f, 1.0f);
    const float r = std::clamp(1.5f - std::abs(4.0f * t - 3.0f), 0.0f, 1.0f);
    const float g = std::clamp(1.5f - std::abs(4.0f * t - 2.0f), 0.0f, 1.0f);
    const float b = std::clamp(1.5f - std::abs(4.0f * t - 1.0f), 0.0f, 1.0f);
    rgb[0] = uint8_t(r * 255.0f + 0.5f);
    rgb[1] = uint8_t(g * 255.0f + 0.5f);
    rgb[2] = uint8_t(b * 255.0f + 0.5f);
}

}  // namespace

void toneMapRect(const DisplayFrame& f, const QRect& r, QImage& image) {
    const std::size_t n = std::size_t(r.width());
    for (int y = r.top(); y <= r.bottom(); ++y) {
        const Color* row = &f.color[std::size_t(y) * std::size_t(f.width) + std::size_t(r.left())];
        uchar* line = image.scanLine(y) + 3 * r.left();
        if (y > r.top() && std::memcmp(row, row - f.width, n * sizeof(Color)) == 0)
            std::memcpy(line, image.scanLine(y - 1) + 3 * r.left(), 3 * n);
        else
            toDisplay8(row, n, f.tonemap, f.exposure, line);
    }
}

QImage toneMappedImage(const DisplayFrame& f) {
    QImage img(f.width, f.height, QImage::Format_RGB888);
    toneMapRect(f, QRect(0, 0, f.width, f.height), img);
    return img;
}

QImage debugImage(const DisplayFrame& f, ViewMode mode) {
    if (mode == ViewMode::Color) return toneMappedImage(f);
    QImage img(f.width, f.height, QImage::Format_RGB888);
    // Normals and costs are handed over only while a debug view shows them: a frame without
    // them (DisplayFrame::debugBuffers off) shows black there instead of reading past the end.
    const std::size_t pixels = std::size_t(f.width) * std::size_t(f.height);
    const bool hasNormals = f.normal.size() == pixels, hasCosts = f.cost.size() == pixels;
    float maxDepth = 0.0f;
    uint32_t maxCost = 1;
    for (std::size_t i = 0; i < f.depth.size(); ++i)
        if (std::isfinite(f.depth[i])) maxDepth = std::max(maxDepth, f.depth[i]);
    if (hasCosts)
        for (uint32_t c : f.cost) maxCost = std::max(maxCost, c);
    for (int y = 0; y < f.height; ++y) {
        uchar* line = img.scanLine(y);
        for (int x = 0; x < f.width; ++x) {
            const std::size_t i = std::size_t(y) * f.width + x;
            uchar* p = line + 3 * x;
            switch (mode) {
                case ViewMode::ObjectIds:
                    idColor(f.id[i], p);
                    break;
                case ViewMode::Normals:
                    for (int c = 0; c < 3; ++c)
                        p[c] = f.id[i] == kNoObject || !hasNormals
                                   ? 0
                                   : uint8_t(std::clamp(0.5f + 0.5f * f.normal[i][c], 0.0f, 1.0f) *
                                             255.0f);
                    break;
                case ViewMode::Depth: {
                    const float d = std::isfinite(f.depth[i]) && maxDepth > 0.0f
                                        ? 1.0f - f.depth[i] / maxDepth
                                        : 0.0f;
                    p[0] = p[1] = p[2] = uint8_t(d * 255.0f);
                    break;
                }
                case ViewMode::Cost:
                    if (!hasCosts) {
                        p[0] = p[1] = p[2] = 0;
                        break;
                    }
                    heat(std::log1p(float(f.cost[i])) / std::log1p(float(maxCost)), p);
                    break;
                case ViewMode::Retraced: {
                    uint8_t c[3];
                    toDisplay8(f.color[i], f.tonemap, f.exposure, c);
                    const bool traced = f.flags[i] & 4;  // kTracedLastUpdate
                    p[0] = traced ? uint8_t(c[0] / 2 + 127) : uint8_t(c[0] / 3);
                    p[1] = traced ? uint8_t(c[1] / 2) : uint8_t(c[1] / 3);
                    p[2] = traced ? uint8_t(c[2] / 2) : uint8_t(c[2] / 3);
                    break;
                }
                case ViewMode::Color:
                    break;
            }
        }
    }
    return img;
}

bool outlined(const std::vector<ObjectId>& selected, ObjectId id) {
    const auto end = selected.begin() + std::ptrdiff_t(std::min(selected.size(), kMaxOutlined));
    return id != kNoObject && std::find(selected.begin(), end, id) != end;
}

bool onOutline(const DisplayFrame& f, int x, int y, const std::vector<ObjectId>& selected) {
    if (selected.empty()) return false;
    const ObjectId c = f.idAt(x, y);
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= f.width || ny >= f.height) continue;
        const ObjectId n = f.idAt(nx, ny);
        if (n != c && (outlined(selected, n) || outlined(selected, c))) return true;
    }
    return false;
}

void drawOutlineRow(const DisplayFrame& f, int y, int x0, int x1,
                    const std::vector<ObjectId>& selected, uint8_t* line) {
    if (selected.empty()) return;
    for (int x = x0; x <= x1; ++x)
        if (atIdEdge(f, x, y) && onOutline(f, x, y, selected))
            std::copy(kOutlineRgb, kOutlineRgb + 3, line + 3 * x);
}

QRect outlinedBounds(const DisplayFrame& f, const std::vector<ObjectId>& a,
                     const std::vector<ObjectId>& b) {
    // The ids either selection outlines, as a plain array: the scan compares every pixel.
    ObjectId ids[2 * kMaxOutlined];
    std::size_t n = 0;
    for (const std::vector<ObjectId>* s : {&a, &b})
        for (std::size_t k = 0; k < std::min(s->size(), kMaxOutlined); ++k)
            if ((*s)[k] != kNoObject && std::find(ids, ids + n, (*s)[k]) == ids + n)
                ids[n++] = (*s)[k];
    if (n == 0) return {};
    const auto hit = [&](ObjectId v) {
        bool any = false;
        for (std::size_t k = 0; k < n; ++k) any |= v == ids[k];
        return any;
    };
    int x0 = f.width, y0 = f.height, x1 = -1, y1 = -1;
    for (int y = 0; y < f.height; ++y) {
        const ObjectId* row = &f.id[std::size_t(y) * f.width];
        int first = 0;
        while (first < f.width && !hit(row[first])) ++first;
        if (first == f.width) continue;
        int last = f.width - 1;
        while (!hit(row[last])) --last;
        x0 = std::min(x0, first), x1 = std::max(x1, last);
        y0 = std::min(y0, y), y1 = y;
    }
    if (x1 < 0) return {};
    return QRect(QPoint(x0, y0), QPoint(x1, y1));
}

QImage viewportImage(const DisplayFrame& f, ViewMode mode, const std::vector<ObjectId>& selected) {
    if (f.empty()) return {};
    QImage img = debugImage(f, mode);
    if (selected.empty()) return img;
    for (int y = 0; y < f.height; ++y)
        drawOutlineRow(f, y, 0, f.width - 1, selected, img.scanLine(y));
    return img;
}

}  // namespace rs::ui
