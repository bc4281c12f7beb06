// PassStatus: fixed-width status-bar fields, refreshed from each finished pass.
#include "shell/pass_status.h"

#include <QLabel>
#include <QStatusBar>
#include <cstdio>

#include "adapter/session_terms.h"

namespace rs::ui {

namespace {
/// The widest name among the governor's levels.
QString widestLevelName() {
    QString widest;
    for (int level = 0; level < Governor::kLevels; ++level) {
        const QString name = QString::fromLatin1(Governor::levelName(level));
        if (name.size() > widest.size()) widest = name;
    }
    return widest;
}
}  // namespace

PassStatus::PassStatus(QStatusBar* bar, QWidget* window) : QObject(window), bar_(bar) {
    // Each field as wide as its widest text, fixed: neighbours do not jump sideways and no
    // text is cut as the numbers change.
    auto label = [bar, window](const QString& tip, const QString& widest) {
        auto* l = new QLabel(window);
        l->setToolTip(tip);
        l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        l->setFixedWidth(l->fontMetrics().horizontalAdvance(widest) + 2 * l->margin() + 12);
        bar->addPermanentWidget(l);
        return l;
    };
    frame_ = label(tr("Wall time of the last pass"), tr("%1 ms").arg(9999.9, 0, 'f', 1));
    ups_ = label(tr("Document updates sent to the renderer per second"), tr("%1 upd/s").arg(999));
    retraced_ = label(tr("Share of the frame's pixels the last pass re-traced"),
                      tr("%1% re-traced").arg(100.0, 0, 'f', 1));
    pass_ = label(tr("Kind of the last pass (interactive, base, supersampling)"),
                  tr("pass: %1%2").arg(QStringLiteral("interactive"), tr(" (cut short)")));
    rays_ = label(tr("Rays per second in the last pass"), tr("%1 Mrays/s").arg(999.99, 0, 'f', 2));
    governor_ = label(tr("What the governor turned down in the last interactive pass to "
                         "keep its frame rate; \"as set\" once the frame refines at the "
                         "scene's settings (Preferences)"),
                      tr("governor: %1").arg(widestLevelName()));
    governor_->setObjectName(QStringLiteral("statusGovernor"));
}

void PassStatus::showPass(const PassInfo& info) {
    static const char* const kinds[] = {"interactive", "base", "supersample"};
    frame_->setText(tr("%1 ms").arg(info.ms, 0, 'f', 1));
    const double share =
        info.totalPixels ? 100.0 * double(info.tracedPixels) / double(info.totalPixels) : 0.0;
    retraced_->setText(tr("%1% re-traced").arg(share, 0, 'f', 1));
    pass_->setText(tr("pass: %1%2")
                       .arg(QString::fromLatin1(kinds[int(info.kind)]),
                            info.cancelled ? tr(" (cut short)") : QString()));
    const double mrays = info.ms > 0.0 ? double(info.rays) / info.ms / 1000.0 : 0.0;
    rays_->setText(tr("%1 Mrays/s").arg(mrays, 0, 'f', 2));
    // Refining passes (base, supersampling) are at the scene's own settings: a level the
    // last drag needed (the box proxy, say) no longer describes the picture after release.
    const int level = info.kind == PassKind::Interactive ? info.governorLevel : 0;
    governor_->setText(
        level < 0 ? tr("governor: off")
                  : tr("governor: %1").arg(QString::fromLatin1(Governor::levelName(level))));
}

void PassStatus::showUpdateRate(double perSecond) {
    ups_->setText(tr("%1 upd/s").arg(perSecond, 0, 'f', 0));
}

void PassStatus::showFailed() {
    pass_->setText(tr("pass: failed"));
}

void PassStatus::showImageProblems(const std::vector<std::string>& problems) {
    const auto keyOf = [](const std::string& problem) {
        return problem.substr(0, problem.find(": "));
    };
    std::set<std::string> now;
    std::vector<const std::string*> fresh;
    for (const std::string& p : problems) {
        const std::string key = keyOf(p);
        if (!saidProblems_.count(key)) fresh.push_back(&p);
        now.insert(key);
    }
    saidProblems_ = std::move(now);  // A mended image is said again if it breaks again.
    if (fresh.empty()) return;
    for (const std::string* p : fresh) std::fprintf(stderr, "%s (warning)\n", p->c_str());
    // The problem first (key, file, why): the status bar's permanent fields leave the message
    // half the bar's width.
    const QString first = QString::fromStdString(*fresh.front());
    bar_->showMessage(fresh.size() == 1 ? tr("%1 (shown as the missing pattern)").arg(first)
                                        : tr("%1, and %n more (shown as the missing pattern)", "",
                                             int(fresh.size()) - 1)
                                              .arg(first),
                      15000);
}

}  // namespace rs::ui
