// The designer measurement's figures from what it recorded, and the text report.
#include "measurement_analysis.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "core/statistics.h"

namespace rs::ui {

namespace {

struct Shown {  ///< Frames presented between two times.
    int frames = 0, generations = 0, wholeFrames = 0;
    std::vector<double> paint, compose;
};

struct Latencies {  ///< From each edit's input to the first frame, and whole frame, showing it.
    std::vector<double> toShown, toWhole;
    int neverShown = 0;
};

struct Passes {  ///< Interactive passes between two times.
    std::vector<double> ms, levels;
    int cancelled = 0;
};

bool isWhole(const Recording& r, const Present& p) {
    return std::binary_search(r.wholeSerials.begin(), r.wholeSerials.end(), p.frame.serial);
}

Shown shownBetween(const Recording& r, MeasureClock::time_point begin,
                   MeasureClock::time_point end) {
    Shown s;
    uint64_t lastSerial = 0, lastGeneration = 0;
    for (const Present& p : r.presents) {
        if (p.time > end) break;
        if (p.time >= begin) {
            s.paint.push_back(p.frame.paintMs);
            s.compose.push_back(p.frame.composeMs);
            s.frames += p.frame.serial != lastSerial;
            // What the user really gets: a new frame none of whose pixels is left from an
            // older camera or position (no pass cut short in it).
            s.wholeFrames += p.frame.serial != lastSerial && isWhole(r, p);
            s.generations += p.frame.generation > lastGeneration;
        }
        lastSerial = p.frame.serial;
        lastGeneration = std::max(lastGeneration, p.frame.generation);
    }
    return s;
}

Latencies editLatencies(const Recording& r) {
    Latencies l;
    for (std::size_t i = 1; i < r.inputs.size(); ++i) {
        if (r.inputs[i].request <= r.inputs[i - 1].request) continue;  // No edit.
        const auto post = std::find_if(r.posted.begin(), r.posted.end(), [&](const auto& p) {
            return p.first >= r.inputs[i].request;
        });
        const auto shown =
            post == r.posted.end()
                ? r.presents.end()
                : std::find_if(r.presents.begin(), r.presents.end(), [&](const Present& p) {
                      return p.time >= r.inputs[i].handled && p.frame.generation >= post->second;
                  });
        if (shown == r.presents.end())
            ++l.neverShown;
        else
            l.toShown.push_back(msBetween(r.inputs[i].due, shown->time));
        // The same to the first whole frame that shows the edit (never: not counted).
        const auto whole = std::find_if(shown, r.presents.end(), [&](const Present& p) {
            return p.frame.generation >= post->second && isWhole(r, p);
        });
        if (whole != r.presents.end()) l.toWhole.push_back(msBetween(r.inputs[i].due, whole->time));
    }
    return l;
}

Passes interactivePasses(const Recording& r, MeasureClock::time_point begin,
                         MeasureClock::time_point end) {
    Passes s;
    for (const auto& [t, info] : r.passes) {
        if (t < begin || t > end || info.kind != PassKind::Interactive) continue;
        s.levels.push_back(info.governorLevel);
        if (info.cancelled)
            ++s.cancelled;
        else
            s.ms.push_back(info.ms);
    }
    return s;
}

}  // namespace

QJsonObject analyseGesture(const Recording& r, MeasureClock::time_point begin,
                           MeasureClock::time_point end) {
    const double seconds = msBetween(begin, end) / 1000.0;
    const Shown shown = shownBetween(r, begin, end);
    const Latencies latency = editLatencies(r);
    std::vector<double> handling;
    for (const Input& in : r.inputs) handling.push_back(msBetween(in.dispatched, in.handled));
    // Which event took longest: the press (selection, panels) is not what a move costs.
    const auto slowest = std::max_element(handling.begin(), handling.end());
    const int slowestAt = slowest == handling.end() ? -1 : int(slowest - handling.begin());
    const Passes passes = interactivePasses(r, begin, end);
    QJsonObject o;
    o[QStringLiteral("seconds")] = seconds;
    o[QStringLiteral("frames_per_s")] = shown.frames / seconds;
    o[QStringLiteral("generations_per_s")] = shown.generations / seconds;
    o[QStringLiteral("whole_frames_per_s")] = shown.wholeFrames / seconds;
    o[QStringLiteral("whole_latency_median_ms")] = median(latency.toWhole);
    o[QStringLiteral("latency_median_ms")] = median(latency.toShown);
    o[QStringLiteral("latency_p90_ms")] = quantile(latency.toShown, 0.9);
    o[QStringLiteral("edits")] = int(latency.toShown.size()) + latency.neverShown;
    o[QStringLiteral("edits_never_shown")] = latency.neverShown;
    o[QStringLiteral("interactive_pass_median_ms")] = median(passes.ms);
    o[QStringLiteral("interactive_passes")] = int(passes.ms.size());
    o[QStringLiteral("interactive_passes_cancelled")] = passes.cancelled;
    o[QStringLiteral("governor_level_median")] = median(passes.levels);
    o[QStringLiteral("governor_level_max")] = quantile(passes.levels, 1.0);
    o[QStringLiteral("input_handling_median_ms")] = median(handling);
    o[QStringLiteral("input_handling_max_ms")] = quantile(handling, 1.0);
    o[QStringLiteral("input_handling_max_at")] = slowestAt;
    o[QStringLiteral("paint_median_ms")] = median(shown.paint);
    o[QStringLiteral("paint_max_ms")] = quantile(shown.paint, 1.0);
    o[QStringLiteral("compose_median_ms")] = median(shown.compose);
    o[QStringLiteral("gui_stall_max_ms")] = std::max(0.0, quantile(r.probeGaps, 1.0) - 1.0);
    o[QStringLiteral("gui_stall_p99_ms")] = std::max(0.0, quantile(r.probeGaps, 0.99) - 1.0);
    double blocked = 0.0, probed = 0.0;
    for (double g : r.probeGaps) blocked += g > 16.0 ? g : 0.0, probed += g;
    o[QStringLiteral("gui_blocked_share")] = probed > 0.0 ? blocked / probed : 0.0;
    return o;
}

void printMeasurementReport(const ReportHeading& heading, const QJsonObject& o) {
    auto num = [&](const char* key) { return o[QLatin1String(key)].toDouble(); };
    std::printf("%s %s%s: %d moves at 60 Hz, viewport %s (%s), frame %s\n",
                qPrintable(o[QStringLiteral("kind")].toString()), qPrintable(heading.scene),
                heading.orbit ? "" : qPrintable(QStringLiteral(" \"%1\"").arg(heading.object)),
                heading.moves, qPrintable(o[QStringLiteral("viewport")].toString()),
                heading.openGL ? "OpenGL" : "raster",
                qPrintable(o[QStringLiteral("frame")].toString()));
    std::printf("  frames shown          %6.1f /s distinct, %.1f /s with a newer edit\n",
                num("frames_per_s"), num("generations_per_s"));
    std::printf(
        "  whole frames shown    %6.1f /s (no pixel of an older edit), input to one "
        "median %.1f ms\n",
        num("whole_frames_per_s"), num("whole_latency_median_ms"));
    std::printf(
        "  input to display     median %6.1f ms   p90 %6.1f ms   (%d edits, %d never shown)\n",
        num("latency_median_ms"), num("latency_p90_ms"), o[QStringLiteral("edits")].toInt(),
        o[QStringLiteral("edits_never_shown")].toInt());
    std::printf("  interactive pass     median %6.1f ms   (%d passes, %d cancelled)\n",
                num("interactive_pass_median_ms"), o[QStringLiteral("interactive_passes")].toInt(),
                o[QStringLiteral("interactive_passes_cancelled")].toInt());
    std::printf("  governor level       median %4.0f (%s)   max %.0f\n",
                num("governor_level_median"),
                Governor::levelName(int(num("governor_level_median"))), num("governor_level_max"));
    std::printf(
        "  frame hand-over      mean   %6.2f ms   max %6.2f ms   (copying %.2f ms of the mean)\n",
        num("handover_mean_ms"), num("handover_max_ms"), num("handover_copy_mean_ms"));
    std::printf("  hand-overs           %6d        %d found the frame lock held and came back\n",
                o[QStringLiteral("handovers")].toInt(),
                o[QStringLiteral("handovers_busy")].toInt());
    const int slowestAt = o[QStringLiteral("input_handling_max_at")].toInt();
    const int events = o[QStringLiteral("moves")].toInt() + 2;  // The press, moves, the release.
    const char* slowest = slowestAt == 0            ? "the press"
                          : slowestAt == events - 1 ? "the release"
                                                    : "a move";
    std::printf("  mouse event handling median %6.2f ms   max %6.2f ms   (event %d of %d: %s)\n",
                num("input_handling_median_ms"), num("input_handling_max_ms"), slowestAt, events,
                slowest);
    std::printf(
        "  paint                median %6.2f ms   max %6.2f ms   then %.2f ms to the swap\n",
        num("paint_median_ms"), num("paint_max_ms"), num("compose_median_ms"));
    std::printf("  idle repaint         paint %6.2f ms   then %.2f ms to the swap\n",
                num("idle_paint_median_ms"), num("idle_compose_median_ms"));
    std::printf(
        "  GUI thread stalls    longest %5.1f ms   p99 %5.1f ms   %3.0f %% of the time in blocks "
        "over 16 ms\n",
        num("gui_stall_max_ms"), num("gui_stall_p99_ms"), 100.0 * num("gui_blocked_share"));
    std::printf("  release to final     %6.1f ms\n", num("release_to_final_shown_ms"));
    std::printf(
        "  full frame           viewport pass %.1f ms, renderImage %.1f ms: %.2fx (medians of %d "
        "interleaved; edit to shown %.1f ms)\n",
        num("viewport_full_frame_ms"), num("render_image_ms"), num("full_frame_ratio"),
        o[QStringLiteral("full_frame_rounds")].toInt(), num("full_frame_to_shown_ms"));
    std::printf("  first frame on open  viewport pass %.1f ms (open to shown %.1f ms)\n",
                num("open_full_frame_ms"), num("open_to_final_shown_ms"));
}

}  // namespace rs::ui
