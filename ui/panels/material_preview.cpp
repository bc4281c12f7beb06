// MaterialPreviews: the preview scene, its key, the swatch and the one-thread render queue.
#include "panels/material_preview.h"

#include <QPainter>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <variant>

#include "core/input_file.h"
#include "core/thread_priority.h"
#include "image/tonemap.h"
#include "integrator/renderer.h"
#include "snapshot/compiled_scene.h"

#ifdef __linux__
#include <sys/resource.h>
#endif

namespace rs::ui {

namespace {

constexpr const char* kPreviewMaterial = "preview";
constexpr const char* kFloorMaterial = "preview floor";
constexpr const char* kWallMaterial = "preview wall";
/// Previews kept: far more than a scene's materials at a few sizes, under 4 MiB at 96 px.
constexpr int kCacheEntries = 256;

/// Lowers the calling thread's priority, as BackgroundArena lowers the session's tracers
/// (core/thread_priority.h): the thread runs nothing but one preview. On Linux the nice value
/// is per thread; elsewhere this does nothing.
void lowerThisThread() {
#ifdef __linux__
    const int nice = getpriority(PRIO_PROCESS, 0);
    setpriority(PRIO_PROCESS, 0, std::min(nice + kBackgroundNiceSteps, 19));
#endif
}

void appendFloat(std::string& out, float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%a,", double(v));
    out += text;
}

void appendColor(std::string& out, const Color& c) {
    appendFloat(out, c.x);
    appendFloat(out, c.y);
    appendFloat(out, c.z);
}

/// 8-bit display colour of a linear colour, clamped as the preview is.
QColor displayColor(const Color& c) {
    uint8_t rgb[3];
    toDisplay8(c, ToneMap::Clamp, 0.0f, rgb);
    return QColor(rgb[0], rgb[1], rgb[2]);
}

Material checkerMaterial(const char* name, Color even, Color odd, float scale) {
    Material m;
    m.name = name;
    m.diffuse = 0.9f;
    m.pattern = CheckerPattern{even, odd, scale};
    return m;
}

/// Traces `scene` on the calling thread; null when cancelled or failed.
QImage renderPreview(const SceneDocument& scene, const std::atomic<bool>* cancel) {
    try {
        // The built-in BVH: three primitives need no Embree device.
        const CompiledScene compiled(scene, nullptr, EngineKind::Builtin);
        RenderOptions options;
        options.threads = 1;
        options.cancel = cancel;
        options.ids = false;
        const RenderResult result = renderImage(compiled, options);
        if (result.cancelled || *cancel) return {};
        const ImageRgb& image = result.image;
        QImage out(image.width, image.height, QImage::Format_RGB888);
        for (int y = 0; y < image.height; ++y)
            toDisplay8(&image.pixels[std::size_t(y) * std::size_t(image.width)],
                       std::size_t(image.width), scene.render.tonemap, scene.render.exposure,
                       out.scanLine(y));
        return out;
    } catch (const std::exception&) {
        return {};  // The swatch stays: a preview is never worth an error box.
    }
}

/// The file's stamp in a key: an image re-saved on disk is a new preview.
std::string stampText(const std::string& path) {
    const FileStamp stamp = fileStampOf(path);
    return stamp.exists ? std::to_string(stamp.modified) + "/" + std::to_string(stamp.size) + "|"
                        : std::string("missing|");
}

}  // namespace

SceneDocument materialPreviewScene(const Material& material, const Environment& environment,
                                   int side) {
    SceneDocument doc;
    doc.render.width = side;
    doc.render.height = side;
    doc.render.maxDepth = 6;  // Through both sides of a glass ball and a mirror or two.
    doc.render.supersampling = 2;
    doc.render.shadowSamples = 1;
    doc.render.tonemap = ToneMap::Clamp;
    doc.render.background = Color(0.42f, 0.42f, 0.45f);
    doc.render.ambient = Color(0.12f, 0.12f, 0.12f);
    doc.camera.position = Vec3(0.0f, 0.9f, 4.3f);
    doc.camera.target = Vec3(0.0f, -0.05f, 0.0f);
    doc.camera.fovY = 33.0f;

    Material m = material;
    m.name = kPreviewMaterial;
    m.extras.clear();
    doc.materials.push_back(m);
    doc.materials.push_back(checkerMaterial(kFloorMaterial, Color(0.75f), Color(0.22f), 0.75f));
    doc.materials.push_back(
        checkerMaterial(kWallMaterial, Color(0.55f, 0.6f, 0.7f), Color(0.18f, 0.2f, 0.25f), 1.0f));

    Light light;
    light.name = "key";
    light.type = LightType::Point;
    light.position = Vec3(-3.0f, 4.5f, 4.0f);
    light.intensity = 1.0f;
    doc.addLight(light);

    Object sphere;
    sphere.name = "ball";
    sphere.material = kPreviewMaterial;
    sphere.geometry = SphereGeometry{Vec3(0.0f), 1.0f};
    doc.addObject(sphere);
    Object floor;
    floor.name = "floor";
    floor.material = kFloorMaterial;
    floor.geometry = PlaneGeometry{Vec3(0.0f, -1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};
    doc.addObject(floor);
    if (environment.present()) {
        doc.environment = environment;
        doc.environment.extras.clear();
    } else {
        Object wall;
        wall.name = "wall";
        wall.material = kWallMaterial;
        wall.geometry = PlaneGeometry{Vec3(0.0f, 0.0f, -3.0f), Vec3(0.0f, 0.0f, 1.0f)};
        doc.addObject(wall);
    }
    return doc;
}

std::string materialPreviewKey(const Material& m, const Environment& environment, int side) {
    std::string key = "side " + std::to_string(side) + ";";
    appendColor(key, m.color);
    for (float v : {m.diffuse, m.specular, m.shininess, m.reflectivity, m.transparency, m.ior})
        appendFloat(key, v);
    if (const auto* checker = std::get_if<CheckerPattern>(&m.pattern)) {
        key += ";checker ";
        appendColor(key, checker->even);
        appendColor(key, checker->odd);
        appendFloat(key, checker->scale);
    } else if (const auto* texture = std::get_if<ImageTexture>(&m.pattern)) {
        key += ";texture " + texture->image.source() + "|" + stampText(texture->image.source());
        for (float v : {texture->scaleU, texture->scaleV, texture->offsetU, texture->offsetV})
            appendFloat(key, v);
    }
    if (environment.present()) {
        key += ";environment " + environment.image.source() + "|" +
               stampText(environment.image.source());
        appendFloat(key, environment.intensity);
        appendFloat(key, environment.rotation);
    }
    return key;
}

QImage materialSwatch(const Material& material, int side) {
    QImage image(side, side, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    const QRectF disc(side * 0.12, side * 0.12, side * 0.76, side * 0.76);
    if (const auto* checker = std::get_if<CheckerPattern>(&material.pattern)) {
        // Halves of the two colours: the checker's look without tracing it.
        p.setBrush(displayColor(checker->even));
        p.drawPie(disc, 90 * 16, 180 * 16);
        p.setBrush(displayColor(checker->odd));
        p.drawPie(disc, 270 * 16, 180 * 16);
    } else {
        const bool image = std::holds_alternative<ImageTexture>(material.pattern);
        p.setBrush(image ? QColor(128, 128, 128) : displayColor(material.color));
        p.drawEllipse(disc);
    }
    return image;
}

MaterialPreviews::MaterialPreviews(QObject* parent)
    : QObject(parent), toGui_(this), cache_(kCacheEntries) {}

MaterialPreviews::~MaterialPreviews() {
    waiting_.clear();
    if (running_) *running_->cancel = true;
    if (worker_.joinable()) worker_.join();  // Within a ray-tree level of a small image.
}

QImage MaterialPreviews::request(const Material& material, const Environment& environment,
                                 int side) {
    const std::string key = materialPreviewKey(material, environment, side);
    // Whatever this name asked for before is stale now.
    std::erase_if(waiting_, [&](const auto& job) { return job->name == material.name; });
    const bool runningThis = running_ && running_->name == material.name;
    if (const QImage* cached = cache_.object(QString::fromStdString(key))) {
        if (runningThis) *running_->cancel = true;
        return *cached;
    }
    if (runningThis) {
        if (running_->key == key) return {};  // Already on its way.
        *running_->cancel = true;
    }
    auto job = std::make_shared<Job>();
    job->name = material.name;
    job->key = key;
    job->scene = materialPreviewScene(material, environment, side);
    job->cancel = std::make_shared<std::atomic<bool>>(false);
    waiting_.push_back(std::move(job));
    if (!running_) startNext();
    return {};
}

void MaterialPreviews::retain(const std::set<std::string>& names) {
    std::erase_if(waiting_, [&](const auto& job) { return !names.count(job->name); });
    if (running_ && !names.count(running_->name)) *running_->cancel = true;
}

void MaterialPreviews::startNext() {
    // A duplicate's twin may have rendered its content meanwhile.
    while (!waiting_.empty()) {
        const QString key = QString::fromStdString(waiting_.front()->key);
        const QImage* cached = cache_.object(key);
        if (!cached) break;
        const QImage image = *cached;
        const QString name = QString::fromStdString(waiting_.front()->name);
        waiting_.pop_front();
        Q_EMIT previewReady(name, key, image);
    }
    if (waiting_.empty()) return;
    running_ = std::move(waiting_.front());
    waiting_.pop_front();
    ++started_;
    worker_ = std::thread([job = running_, toGui = toGui_, this] {
        lowerThisThread();
        const QImage image = renderPreview(job->scene, job->cancel.get());
        // Runs on the GUI thread, and not at all once this object is gone.
        toGui.post([this, job, image] { finished(job, image); });
    });
}

void MaterialPreviews::finished(const std::shared_ptr<Job>& job, const QImage& image) {
    // The worker's last act was the post that brought us here: the join is immediate.
    if (worker_.joinable()) worker_.join();
    if (running_ == job) running_.reset();
    // A cancelled job's image is stale (its material changed or went): dropped.
    if (!*job->cancel && !image.isNull()) {
        const QString key = QString::fromStdString(job->key);
        cache_.insert(key, new QImage(image));
        Q_EMIT previewReady(QString::fromStdString(job->name), key, image);
    }
    if (!running_) startNext();
}

}  // namespace rs::ui
