// Theme icons with bundled SVG fallbacks (drawn for the project, resources/icons/actions/).
#include "shell/action_icons.h"

#include <QString>

namespace rs::ui {

QIcon actionIcon(const char* themeName, const char* bundled) {
    const QIcon fallback(QStringLiteral(":/icons/actions/%1.svg").arg(QLatin1String(bundled)));
    if (!themeName || !*themeName) return fallback;
    return QIcon::fromTheme(QLatin1String(themeName), fallback);
}

}  // namespace rs::ui
