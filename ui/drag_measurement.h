// The designer's end-to-end speed test: real mouse events into the real main window, timed
// from each event to the paint of the first frame that shows its edit.
#pragma once

class QCommandLineParser;

namespace rs::ui {

/// Adds --measure-drag SCENE, --measure-orbit SCENE, --object NAME, --frames N and --json.
void addMeasurementOptions(QCommandLineParser& parser);

/// Runs the measurement the parsed options ask for and returns the exit code (0 measured,
/// 2 bad input, 1 failure); -1 when no measurement was asked for.
int runRequestedMeasurement(const QCommandLineParser& parser);

}  // namespace rs::ui
