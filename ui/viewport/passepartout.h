// The passepartout of "View -> Through Scene Camera": what lies outside the output frame, dimmed.
#pragma once

#include <QRect>
#include <QRectF>

class QPainter;

namespace rs::ui {

/// Share of the picture's light kept outside the output frame.
inline constexpr double kPassepartoutKeep = 0.35;

/// Dims `area` outside `outputFrame` and outlines the frame (widget coordinates); nothing when
/// `outputFrame` is empty.
void paintPassepartout(QPainter& p, const QRect& area, const QRectF& outputFrame);

}  // namespace rs::ui
