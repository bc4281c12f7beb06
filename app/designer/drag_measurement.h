// The designer's end-to-end speed test: real mouse events into the real main window, timed
// from each event to the paint of the first frame that shows its edit.
#pragma once

#include <functional>

class QCommandLineParser;
class QWidget;

namespace rs::ui {

/// Adds --measure-drag SCENE, --measure-orbit SCENE, --object NAME, --frames N and --json.
void addMeasurementOptions(QCommandLineParser& parser);

/// Runs the measurement the parsed options ask for and returns the exit code (0 measured,
/// 2 bad input, 1 failure); -1 when no measurement was asked for. `afterOpen`, when set, is
/// called with the main window once the opened scene is shown (tests resize it there, as a
/// dock taking its width late would).
int runRequestedMeasurement(const QCommandLineParser& parser,
                            const std::function<void(QWidget&)>& afterOpen = {});

}  // namespace rs::ui
