// Measures what the user feels while dragging or orbiting: the real window, mouse events
// posted to the viewport at 60 Hz, and timestamps from the event queue to the swapped frame.
// This file drives the window and records (measurement_record.h); measurement_analysis.cpp
// turns the recording into figures.
#include "drag_measurement.h"

#include <QCommandLineParser>
#include <QEventLoop>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMouseEvent>
#include <QStandardPaths>
#include <QTimer>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "adapter/session_controller.h"
#include "core/statistics.h"
#include "display/display_choice.h"
#include "document/scene_editor.h"
#include "integrator/renderer.h"
#include "measurement_analysis.h"
#include "measurement_record.h"
#include "shell/error_reporter.h"
#include "shell/main_window.h"
#include "shell/preferences.h"
#include "viewport/viewport.h"

namespace rs::ui {

namespace {

using Clock = MeasureClock;

struct Request {
    bool orbit = false;
    QString scene;
    QString object;
    int frames = 240;
    bool json = false;
    DisplayKind display = DisplayKind::Automatic;  ///< --view: who draws the viewport.
    std::function<void(QWidget&)> afterOpen;       ///< Called once the scene is shown.
};

class Measurement {
public:
    explicit Measurement(const Request& request) : request_(request) {}
    int run();

private:
    bool waitUntil(const std::function<bool()>& done, int timeoutMs);
    bool waitFinalShown(Clock::time_point* shownAt);
    bool waitViewSettled();
    QPoint pathPoint(QPoint start, int i) const;
    void post(int i, QPoint start);
    struct FullFrames {
        double passMs = 0.0;    ///< The session's passes of the frame (median).
        double shownMs = 0.0;   ///< Posting the edit to the complete frame painted (median).
        double renderMs = 0.0;  ///< renderImage of the same view document (median).
        int rounds = 0;
    };
    bool measureFullFrames(FullFrames& out);

    // run's steps, in order.
    /// Records presented frames, posted documents, whole hand-overs, passes and completions.
    void connectRecorders();
    /// Shows the window and opens the scene until its first frame is final and shown; 0, or
    /// the exit status.
    int openScene();
    /// What a repaint costs with the session idle.
    void measureIdleRepaint();
    /// The widget point at the centre of the object the drag moves; false (said) if none.
    bool findObjectCentre(const DisplayFrame& frame, QPoint& start) const;
    /// Posts the press, the moves and the release at 60 Hz and waits for the final frame.
    bool driveGesture(QPoint start);
    /// The report's facts besides the gesture's figures (measurement_analysis.h).
    void addRunFacts(QJsonObject& o, const DisplayFrame& frame) const;

    /// What run gathers besides the gesture's events, for the report.
    struct Facts {
        Clock::time_point openStart, openShown, finalShown;
        double openPassMs = 0.0;
        FullFrames full;
        std::vector<double> idlePaint, idleCompose;
        SessionController::HandoverStats handover0;
    };

    Request request_;
    MainWindow window_;
    Recording rec_;
    FrameView* view_ = nullptr;
    Facts facts_;
};

bool Measurement::waitUntil(const std::function<bool()>& done, int timeoutMs) {
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
    QEventLoop loop;
    QTimer poll;
    poll.setInterval(5);
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done() || Clock::now() > deadline) loop.quit();
    });
    poll.start();
    if (!done()) loop.exec();
    return done();
}

/// Waits until the session's current generation is final and a paint has shown it.
bool Measurement::waitFinalShown(Clock::time_point* shownAt) {
    SessionController* c = window_.session();
    if (!waitUntil([&] { return rec_.completed >= c->session().generation(); }, 120000))
        return false;
    const uint64_t serial = window_.viewport()->frame() ? window_.viewport()->frame()->serial : 0;
    window_.viewport()->frameView()->repaintOverlay();  // Paints again, whichever view.
    const bool ok = waitUntil(
        [&] { return !rec_.presents.empty() && rec_.presents.back().frame.serial >= serial; },
        10000);
    if (ok && shownAt) *shownAt = rec_.presents.back().time;
    return ok;
}

/// A figure of eight around `start`, one turn every two seconds at 60 Hz.
QPoint Measurement::pathPoint(QPoint start, int i) const {
    const QSize s = window_.viewport()->size();
    const double a = 0.15 * std::min(s.width(), s.height());
    const double phase = 2.0 * M_PI * i / 120.0;
    return start + QPoint(int(std::lround(a * std::sin(phase))),
                          int(std::lround(0.4 * a * std::sin(2.0 * phase))));
}

void Measurement::post(int i, QPoint start) {
    const int last = int(rec_.inputs.size()) - 1;
    const QEvent::Type type = i == 0      ? QEvent::MouseButtonPress
                              : i == last ? QEvent::MouseButtonRelease
                                          : QEvent::MouseMove;
    const Qt::MouseButton button = request_.orbit ? Qt::RightButton : Qt::LeftButton;
    QWidget* vp = window_.viewport();
    const QPoint p = i == 0 ? start : pathPoint(start, std::min(i, last - 1));
    QCoreApplication::postEvent(
        vp, new QMouseEvent(type, QPointF(p), QPointF(vp->mapToGlobal(p)),
                            type == QEvent::MouseMove ? Qt::NoButton : button,
                            type == QEvent::MouseButtonRelease ? Qt::NoButton : button,
                            Qt::NoModifier));
    // Posted events are delivered in order: this runs right after the viewport handled it.
    QMetaObject::invokeMethod(
        vp,
        [this, i] {
            rec_.inputs[std::size_t(i)].handled = Clock::now();
            rec_.inputs[std::size_t(i)].request = window_.session()->requestSerial();
        },
        Qt::QueuedConnection);
}

/// Rounds of measureFullFrames: an even number, so the view ends as it was opened.
constexpr int kFullFrameRounds = 4;
/// Rounds measureFullFrames may repeat because a resize superseded them.
constexpr int kFullFrameRepeats = 8;

/// Waits until the viewport has kept its size for twice the time a resize takes to reach the
/// session, the session traces that size and its frame is final and shown. A dock that takes
/// its width after the open resizes the viewport; the new size is posted once it rests.
bool Measurement::waitViewSettled() {
    Viewport* v = window_.viewport();
    QSize size = v->size();
    auto since = Clock::now();
    const bool rested = waitUntil(
        [&] {
            if (v->size() != size) size = v->size(), since = Clock::now();
            const QSize traced =
                tracedFrameSize(size * v->devicePixelRatioF(), v->previewDivider());
            return msBetween(since, Clock::now()) > 2.0 * Viewport::kResizeSettleMs &&
                   v->tracedSize() == traced;
        },
        20000);
    return rested && waitFinalShown(nullptr);
}

/// Viewport full frames against renderImage, like with like: the same view document (the
/// viewport's traced size and camera, the scene's samples), the same thread count, both after
/// the open has settled and interleaved so that both see the same machine load. A frame is a
/// camera nudge (every pixel re-traced); its time is the session's passes for it (Base, and
/// Supersample where the scene asks), as renderImage's is its tracing (snapshot built before).
/// A round that another post superseded (the viewport's new size) is measured again.
bool Measurement::measureFullFrames(FullFrames& out) {
    SessionController* c = window_.session();
    RenderOptions options;
    options.threads = loadPreferences().threads;
    std::vector<double> pass, shown, image;
    for (int k = 0, repeats = 0; k < kFullFrameRounds;) {
        if (!waitViewSettled()) return false;
        SceneDocument doc = window_.viewport()->viewDocument();  // At the size traced now.
        if (k % 2 == 0) doc.camera.target.x += 1e-3f;            // Odd rounds go back to the view.
        const std::size_t seen = rec_.passes.size();
        const auto start = Clock::now();
        c->requestUpdate(doc);
        c->flushUpdate();
        const uint64_t generation = c->session().generation();
        Clock::time_point shownAt;
        if (!waitFinalShown(&shownAt)) return false;
        if (c->session().generation() != generation) {
            if (++repeats > kFullFrameRepeats) {
                std::fprintf(stderr, "raystudio: the viewport kept changing size\n");
                return false;
            }
            continue;
        }
        double ms = 0.0;
        std::size_t traced = 0;
        for (std::size_t p = seen; p < rec_.passes.size(); ++p) {
            const PassInfo& info = rec_.passes[p].second;
            if (info.generation != generation || info.cancelled) continue;
            ms += info.ms;
            if (info.kind == PassKind::Base) traced += info.tracedPixels;
        }
        if (traced != std::size_t(doc.render.width) * std::size_t(doc.render.height)) {
            std::fprintf(stderr, "raystudio: a full frame traced %zu of %d x %d pixels\n", traced,
                         doc.render.width, doc.render.height);
            return false;
        }
        pass.push_back(ms);
        shown.push_back(msBetween(start, shownAt));
        const CompiledScene scene(doc);
        image.push_back(renderImage(scene, options).ms);
        ++k;
    }
    out = {median(pass), median(shown), median(image), kFullFrameRounds};
    return true;
}

void Measurement::connectRecorders() {
    SessionController* controller = window_.session();
    window_.viewport()->setDisplay(request_.display);
    view_ = window_.viewport()->frameView();
    view_->setPresentedHandler([this](const PresentedFrame& f) {
        rec_.presents.push_back({Clock::now(), f});
    });
    QObject::connect(controller, &SessionController::documentPosted, &window_,
                     [this](quint64 r, quint64 g) { rec_.posted.emplace_back(r, g); });
    QObject::connect(controller, &SessionController::frameHandedOver, &window_,
                     [this](quint64 serial, bool whole) {
                         if (whole) rec_.wholeSerials.push_back(serial);
                     });
    QObject::connect(controller, &SessionController::passFinished, &window_,
                     [this](const PassInfo& p) { rec_.passes.emplace_back(Clock::now(), p); });
    QObject::connect(controller, &SessionController::frameCompleted, &window_,
                     [this](quint64 g) { rec_.completed = std::max<uint64_t>(rec_.completed, g); });
}

int Measurement::openScene() {
    SessionController* controller = window_.session();
    window_.resize(1600, 1000);
    window_.show();
    waitUntil([&] { return window_.isVisible() && window_.viewport()->isVisible(); }, 5000);
    waitUntil([] { return false; }, 300);  // Let the window manager settle the geometry.
    facts_.openStart = Clock::now();
    if (!window_.openFile(request_.scene)) return 2;
    controller->flushUpdate();
    const uint64_t openGeneration = controller->session().generation();
    if (!waitFinalShown(&facts_.openShown)) {
        std::fprintf(stderr, "raystudio: the opened scene never completed\n");
        return 1;
    }
    // The scene's first full pass, right after the open (while the window fills its panels
    // and caches are cold): reported, but not what the full frame is compared by.
    for (const auto& [t, p] : rec_.passes)
        if (p.generation >= openGeneration && !p.cancelled && p.kind == PassKind::Base &&
            p.tracedPixels == p.totalPixels) {
            facts_.openPassMs = p.ms;
            break;
        }
    return 0;
}

void Measurement::measureIdleRepaint() {
    for (int k = 0; k < 10; ++k) {
        const std::size_t seen = rec_.presents.size();
        window_.viewport()->refresh();
        window_.viewport()->frameView()->repaintOverlay();  // Nothing new: paint all the same.
        if (!waitUntil([&] { return rec_.presents.size() > seen; }, 5000)) break;
        facts_.idlePaint.push_back(rec_.presents.back().frame.paintMs);
        facts_.idleCompose.push_back(rec_.presents.back().frame.composeMs);
    }
}

bool Measurement::findObjectCentre(const DisplayFrame& frame, QPoint& start) const {
    ObjectId id = kNoObject;
    for (const Object& o : window_.editor()->document().objects)
        if (QString::fromStdString(o.name) == request_.object) id = o.id;
    long sx = 0, sy = 0, n = 0;
    for (int y = 0; id != kNoObject && y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x)
            if (frame.idAt(x, y) == id) sx += x, sy += y, ++n;
    if (n == 0) {
        std::fprintf(stderr, "raystudio: no visible object named \"%s\"\n",
                     qPrintable(request_.object));
        return false;
    }
    start = window_.viewport()->widgetPointOf(int(sx / n), int(sy / n));
    if (frame.idAt(int(sx / n), int(sy / n)) != id) {
        std::fprintf(stderr, "raystudio: the centre of \"%s\" shows another object\n",
                     qPrintable(request_.object));
        return false;
    }
    return true;
}

bool Measurement::driveGesture(QPoint start) {
    rec_.inputs.assign(std::size_t(request_.frames) + 2, Input{});
    const auto t0 = Clock::now() + std::chrono::milliseconds(50);
    for (std::size_t i = 0; i < rec_.inputs.size(); ++i)
        rec_.inputs[i].due = t0 + std::chrono::microseconds(int64_t(i * 1000000 / 60));
    std::size_t next = 0;
    QTimer driver, probe;
    driver.setTimerType(Qt::PreciseTimer);
    driver.setInterval(2);
    QObject::connect(&driver, &QTimer::timeout, [&] {
        // Events due while the GUI thread was blocked are posted late but keep their due time,
        // as a window system would queue them.
        while (next < rec_.inputs.size() && Clock::now() >= rec_.inputs[next].due)
            post(int(next++), start);
    });
    probe.setTimerType(Qt::PreciseTimer);
    probe.setInterval(1);
    auto lastProbe = Clock::now();
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const auto now = Clock::now();
        rec_.probeGaps.push_back(msBetween(lastProbe, now));
        lastProbe = now;
    });
    DispatchRecorder recorder(rec_.inputs);
    window_.viewport()->installEventFilter(&recorder);
    driver.start();
    probe.start();
    const bool handled =
        waitUntil([&] { return rec_.inputs.back().handled != Clock::time_point{}; },
                  60000 + request_.frames * 100);
    probe.stop();
    driver.stop();
    window_.viewport()->removeEventFilter(&recorder);
    return handled && waitFinalShown(&facts_.finalShown);
}

void Measurement::addRunFacts(QJsonObject& o, const DisplayFrame& frame) const {
    const auto& handover = window_.session()->handoverStats();
    const auto& handover0 = facts_.handover0;
    const int handovers = handover.count - handover0.count;
    const FullFrames& full = facts_.full;
    o[QStringLiteral("kind")] = request_.orbit ? QStringLiteral("orbit") : QStringLiteral("drag");
    o[QStringLiteral("scene")] = request_.scene;
    o[QStringLiteral("object")] = request_.object;
    o[QStringLiteral("moves")] = request_.frames;
    o[QStringLiteral("opengl")] = view_->usesOpenGL();
    o[QStringLiteral("viewport")] =
        QStringLiteral("%1x%2").arg(window_.viewport()->width()).arg(window_.viewport()->height());
    o[QStringLiteral("frame")] = QStringLiteral("%1x%2").arg(frame.width).arg(frame.height);
    o[QStringLiteral("handover_mean_ms")] =
        handovers > 0 ? (handover.totalMs - handover0.totalMs) / handovers : 0.0;
    o[QStringLiteral("handover_max_ms")] = handover.maxMs;
    o[QStringLiteral("handover_copy_mean_ms")] =
        handovers > 0 ? (handover.copyMs - handover0.copyMs) / handovers : 0.0;
    o[QStringLiteral("handovers")] = handovers;
    o[QStringLiteral("handovers_busy")] = handover.busy - handover0.busy;
    o[QStringLiteral("release_to_final_shown_ms")] =
        msBetween(rec_.inputs.back().due, facts_.finalShown);
    o[QStringLiteral("viewport_full_frame_ms")] = full.passMs;
    o[QStringLiteral("full_frame_to_shown_ms")] = full.shownMs;
    o[QStringLiteral("render_image_ms")] = full.renderMs;
    o[QStringLiteral("full_frame_ratio")] = full.renderMs > 0.0 ? full.passMs / full.renderMs : 0.0;
    o[QStringLiteral("full_frame_rounds")] = full.rounds;
    o[QStringLiteral("open_full_frame_ms")] = facts_.openPassMs;
    o[QStringLiteral("open_to_final_shown_ms")] = msBetween(facts_.openStart, facts_.openShown);
    o[QStringLiteral("idle_paint_median_ms")] = median(facts_.idlePaint);
    o[QStringLiteral("idle_compose_median_ms")] = median(facts_.idleCompose);
}

int Measurement::run() {
    connectRecorders();
    if (const int rc = openScene(); rc != 0) return rc;
    if (request_.afterOpen) request_.afterOpen(window_);
    if (!measureFullFrames(facts_.full)) {
        std::fprintf(stderr, "raystudio: a full frame never completed\n");
        return 1;
    }
    // What a repaint costs with the session idle, to tell display cost from CPU contention.
    measureIdleRepaint();

    const auto frame = window_.viewport()->frame();
    QPoint start = window_.viewport()->rect().center();
    if (!request_.orbit && !findObjectCentre(*frame, start)) return 2;

    facts_.handover0 = window_.session()->handoverStats();
    if (!driveGesture(start)) {
        std::fprintf(stderr, "raystudio: the %s did not finish\n",
                     request_.orbit ? "orbit" : "drag");
        return 1;
    }

    QJsonObject o = analyseGesture(rec_, rec_.inputs.front().due, rec_.inputs.back().due);
    addRunFacts(o, *frame);
    window_.editor()->undoStack()->setClean();  // No save prompt.

    if (request_.json) {
        std::printf("%s\n", QJsonDocument(o).toJson(QJsonDocument::Compact).constData());
        return 0;
    }
    printMeasurementReport(
        {request_.scene, request_.object, request_.orbit, request_.frames, view_->usesOpenGL()}, o);
    return 0;
}

}  // namespace

void addMeasurementOptions(QCommandLineParser& parser) {
    parser.addOption({QStringLiteral("measure-drag"),
                      QStringLiteral("Measure dragging --object in SCENE, then exit."),
                      QStringLiteral("SCENE")});
    parser.addOption({QStringLiteral("measure-orbit"),
                      QStringLiteral("Measure orbiting the camera in SCENE, then exit."),
                      QStringLiteral("SCENE")});
    parser.addOption(
        {QStringLiteral("object"), QStringLiteral("Object to drag."), QStringLiteral("NAME")});
    parser.addOption({QStringLiteral("frames"), QStringLiteral("Mouse moves (60 per second)."),
                      QStringLiteral("N"), QStringLiteral("240")});
    parser.addOption(
        {QStringLiteral("json"), QStringLiteral("Print the measurement as one JSON line.")});
    parser.addOption({QStringLiteral("view"),
                      QStringLiteral("Viewport display: automatic, opengl or software."),
                      QStringLiteral("KIND"), QStringLiteral("automatic")});
}

int runRequestedMeasurement(const QCommandLineParser& parser,
                            const std::function<void(QWidget&)>& afterOpen) {
    Request r;
    r.afterOpen = afterOpen;
    r.orbit = parser.isSet(QStringLiteral("measure-orbit"));
    if (!r.orbit && !parser.isSet(QStringLiteral("measure-drag"))) return -1;
    r.scene =
        parser.value(r.orbit ? QStringLiteral("measure-orbit") : QStringLiteral("measure-drag"));
    r.object = parser.value(QStringLiteral("object"));
    bool ok = false;
    r.frames = parser.value(QStringLiteral("frames")).toInt(&ok);
    r.json = parser.isSet(QStringLiteral("json"));
    if (!parseDisplayKind(parser.value(QStringLiteral("view")), r.display)) {
        std::fprintf(stderr,
                     "raystudio: --view must be automatic, opengl or software, not \"%s\"\n",
                     qPrintable(parser.value(QStringLiteral("view"))));
        return 2;
    }
    if (!ok || r.frames < 2 || (!r.orbit && r.object.isEmpty())) {
        std::fprintf(stderr,
                     "raystudio: --measure-drag needs --object NAME; --frames needs N >= 2\n");
        return 2;
    }
    QStandardPaths::setTestModeEnabled(true);  // Default preferences, not the user's.
    setErrorHandler([](const QString& title, const QString& text) {
        std::fprintf(stderr, "raystudio: %s: %s\n", qPrintable(title), qPrintable(text));
    });
    Measurement m(r);
    return m.run();
}

}  // namespace rs::ui
