// The designer measurement's figures: what a recorded gesture gave the user (frames shown,
// whole frames, input-to-display latency, passes, GUI stalls), and the report printed.
#pragma once

#include <QJsonObject>
#include <QString>

#include "measurement_record.h"

namespace rs::ui {

/// The gesture's figures between its first and last input's due times.
QJsonObject analyseGesture(const Recording& r, MeasureClock::time_point begin,
                           MeasureClock::time_point end);

/// What the report's heading names besides the figures.
struct ReportHeading {
    QString scene, object;
    bool orbit = false;
    int moves = 0;
    bool openGL = false;
};

/// Prints the figures (analyseGesture's and the run's other facts) as text on stdout.
void printMeasurementReport(const ReportHeading& heading, const QJsonObject& o);

}  // namespace rs::ui
