// Preferences: the session's interaction policy, thread count and autosave interval, stored in
// QSettings, and the dialog that edits them live.
#pragma once

#include <QDialog>

class QFormLayout;

#include "accel/ray_engine.h"
#include "adapter/session_terms.h"
#include "display/display_choice.h"
#include "texture/texture_store.h"

namespace rs::ui {

/// What Preferences holds.
struct Preferences {
    InteractionPolicy policy;
    int threads = 0;                         ///< 0: all cores.
    EngineKind engine = EngineKind::Embree;  ///< Who answers the ray queries.
    int renderThreads = 0;     ///< Render Image's threads, shared with the viewport; 0: all cores.
    int autosaveSeconds = 60;  ///< Autosave interval while the document is modified; 0: off.
    /// The viewport traces 1 / previewDivider of its device pixels a side (1, 2 or 4).
    int previewDivider = 1;
    /// Which frame view draws the viewport (display_choice.h has the Automatic rule).
    DisplayKind display = DisplayKind::Automatic;
    /// The texture cache's bound in MB (TextureStore, process-wide).
    int textureCacheMegabytes = int(kDefaultTextureCacheMegabytes);
};

/// Frames per second the governor aims at for a target frame time (0: off), and back.
int governorRate(double targetMs);
double governorTargetMs(int framesPerSecond);

/// Reads preferences from QSettings (defaults where absent or unreadable) and applies those
/// that belong to the whole process rather than a window: the texture cache's bound.
Preferences loadPreferences();
/// Applies the process-wide preferences (TextureStore::shared().setCacheMegabytes).
void applyProcessPreferences(const Preferences& prefs);
/// Writes preferences to QSettings (the policy as policyToJson text).
void savePreferences(const Preferences& prefs);

/// One control per interaction policy setting plus the thread count and the ray engine; every
/// change is announced at once through changed() so the session follows live (the texture
/// cache, which is the process's, the dialog applies itself).
class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    PreferencesDialog(const Preferences& prefs, QWidget* parent = nullptr);
    /// The preferences as the controls show them.
    Preferences preferences() const { return prefs_; }

Q_SIGNALS:
    void changed(const rs::ui::Preferences& prefs);

private:
    void notify();
    // The constructor's rows, top to bottom.
    void addViewRows(QFormLayout* form);     ///< Preview scale, display.
    void addPolicyRows(QFormLayout* form);   ///< The governor, then the interaction policy.
    void addThreadRows(QFormLayout* form);   ///< Viewport and Render Image threads, ray engine.
    void addKeepingRows(QFormLayout* form);  ///< Autosave, the texture cache.

    Preferences prefs_;
};

}  // namespace rs::ui
