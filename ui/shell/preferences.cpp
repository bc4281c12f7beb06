// Preferences storage and the dialog: the policy's controls come from its descriptors.
#include "shell/preferences.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QThread>
#include <algorithm>
#include <cmath>

#include "panels/parameter_widgets.h"
#include "viewport/view_projection.h"

namespace rs::ui {

namespace {
/// What the texture cache may be set to: below 16 MB OpenImageIO thrashes on one 4k texture;
/// 64 GB is more than any machine this runs on would give it.
constexpr int kMinTextureCacheMegabytes = 16;
constexpr int kMaxTextureCacheMegabytes = 65536;
}  // namespace

Preferences loadPreferences() {
    QSettings s;
    Preferences p;
    const QString json = s.value(QStringLiteral("session/policy")).toString();
    std::string error;
    if (!json.isEmpty() && !policyFromJson(json.toStdString(), p.policy, error)) p.policy = {};
    p.threads = s.value(QStringLiteral("session/threads"), 0).toInt();
    p.renderThreads = std::max(0, s.value(QStringLiteral("render/threads"), 0).toInt());
    if (!parseEngineKind(s.value(QStringLiteral("session/engine"), QStringLiteral("embree"))
                             .toString()
                             .toStdString(),
                         p.engine))
        p.engine = EngineKind::Embree;
    p.autosaveSeconds =
        std::max(0, s.value(QStringLiteral("autosave/seconds"), p.autosaveSeconds).toInt());
    p.previewDivider = s.value(QStringLiteral("viewport/previewDivider"), 1).toInt();
    if (!validPreviewDivider(p.previewDivider)) p.previewDivider = 1;
    if (!parseDisplayKind(s.value(QStringLiteral("viewport/display")).toString(), p.display))
        p.display = DisplayKind::Automatic;
    p.textureCacheMegabytes =
        s.value(QStringLiteral("textures/cacheMegabytes"), p.textureCacheMegabytes).toInt();
    if (p.textureCacheMegabytes < kMinTextureCacheMegabytes ||
        p.textureCacheMegabytes > kMaxTextureCacheMegabytes)
        p.textureCacheMegabytes = int(kDefaultTextureCacheMegabytes);
    applyProcessPreferences(p);
    return p;
}

void applyProcessPreferences(const Preferences& p) {
    TextureStore::shared().setCacheMegabytes(float(p.textureCacheMegabytes));
}

void savePreferences(const Preferences& p) {
    QSettings s;
    s.setValue(QStringLiteral("session/policy"), QString::fromStdString(policyToJson(p.policy)));
    s.setValue(QStringLiteral("session/threads"), p.threads);
    s.setValue(QStringLiteral("render/threads"), p.renderThreads);
    s.setValue(QStringLiteral("session/engine"), QString::fromLatin1(engineName(p.engine)));
    s.setValue(QStringLiteral("autosave/seconds"), p.autosaveSeconds);
    s.setValue(QStringLiteral("viewport/previewDivider"), p.previewDivider);
    s.setValue(QStringLiteral("viewport/display"), QString::fromLatin1(displayKindName(p.display)));
    s.setValue(QStringLiteral("textures/cacheMegabytes"), p.textureCacheMegabytes);
}

int governorRate(double targetMs) {
    return targetMs > 0.0 ? std::max(1, int(std::lround(1000.0 / targetMs))) : 0;
}

double governorTargetMs(int framesPerSecond) {
    return framesPerSecond > 0 ? 1000.0 / framesPerSecond : 0.0;
}

namespace {

template <class E>
QComboBox* enumCombo(QWidget* parent, const char* name, QStringList items, E value) {
    auto* c = new QComboBox(parent);
    c->setObjectName(QString::fromLatin1(name));
    c->addItems(items);
    c->setCurrentIndex(int(value));
    return c;
}

}  // namespace

PreferencesDialog::PreferencesDialog(const Preferences& prefs, QWidget* parent)
    : QDialog(parent), prefs_(prefs) {
    setWindowTitle(tr("Preferences"));
    auto* form = new QFormLayout(this);
    addViewRows(form);
    addPolicyRows(form);
    addThreadRows(form);
    addKeepingRows(form);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::accept);
    form->addRow(buttons);
}

void PreferencesDialog::notify() {
    Q_EMIT changed(prefs_);
}

void PreferencesDialog::addViewRows(QFormLayout* form) {
    // The viewport traces its own size; the document's render size is Render Image's.
    auto* preview = enumCombo(this, "previewScale", {tr("1 (every pixel)"), tr("1/2"), tr("1/4")},
                              prefs_.previewDivider == 4   ? 2
                              : prefs_.previewDivider == 2 ? 1
                                                           : 0);
    preview->setToolTip(
        tr("The viewport traces this share of its pixels a side (Blender's pixel size)"));
    connect(preview, &QComboBox::currentIndexChanged, this, [=, this](int i) {
        prefs_.previewDivider = 1 << i;
        notify();
    });
    form->addRow(tr("Viewport preview scale"), preview);

    auto* display =
        enumCombo(this, "display", {tr("Automatic"), tr("OpenGL"), tr("Software")}, prefs_.display);
    display->setToolTip(
        tr("Automatic: OpenGL on a graphics card, Software (QPainter, only the changed "
           "rectangles) on software OpenGL such as llvmpipe, whose drawing takes the cores "
           "the ray tracer needs"));
    connect(display, &QComboBox::currentIndexChanged, this, [=, this](int i) {
        prefs_.display = DisplayKind(i);
        notify();
    });
    form->addRow(tr("Display"), display);
}

void PreferencesDialog::addPolicyRows(QFormLayout* form) {
    // The governor first: while it is on it decides, frame by frame, what the fixed choices
    // below would.
    auto* governor = new QSpinBox(this);
    governor->setObjectName(QStringLiteral("governor"));
    governor->setRange(0, 240);
    governor->setSuffix(tr(" frames/s"));
    governor->setSpecialValueText(tr("Off"));
    governor->setValue(governorRate(prefs_.policy.governorTargetMs));
    connect(governor, &QSpinBox::valueChanged, this, [=, this](int v) {
        prefs_.policy.governorTargetMs = governorTargetMs(v);
        notify();
    });
    form->addRow(tr("Governor: frames per second"), governor);
    auto* governorNote = new QLabel(
        tr("While the governor is on it overrides the settings below, frame by frame, so that "
           "a drag keeps this rate: it defers shadows, then halves the resolution, and only "
           "when that is not enough shows mirrors and glass as diffuse, quarters the "
           "resolution and draws the moving object as its box. Off: exactly the settings "
           "below."),
        this);
    governorNote->setObjectName(QStringLiteral("governorNote"));
    governorNote->setWordWrap(true);
    form->addRow(governorNote);

    // One editor per policy setting, generated from the descriptors the session publishes
    // (render/session/interaction_policy.h): their keys, labels, ranges and defaults.
    for (const ParamDescriptor& d : policyParameters()) {
        const std::string key = d.key;
        ParamEditor editor = makeParamEditor(d, this, [=, this](const ParamValue& v) {
            if (setPolicyParameter(prefs_.policy, key, v).empty()) notify();
        });
        if (auto v = getPolicyParameter(prefs_.policy, key)) editor.setValue(*v);
        form->addRow(QString::fromStdString(d.label), editor.widget);
    }
}

void PreferencesDialog::addThreadRows(QFormLayout* form) {
    auto* threads = new QSpinBox(this);
    threads->setObjectName(QStringLiteral("threads"));
    threads->setRange(0, std::max(64, QThread::idealThreadCount()));
    threads->setSpecialValueText(tr("All cores"));
    threads->setValue(prefs_.threads);
    connect(threads, &QSpinBox::valueChanged, this, [=, this](int v) {
        prefs_.threads = v;
        notify();
    });
    form->addRow(tr("Render threads"), threads);

    // Render Image runs beside the viewport; fewer threads here leave the viewport its share.
    auto* renderThreads = new QSpinBox(this);
    renderThreads->setObjectName(QStringLiteral("renderThreads"));
    renderThreads->setRange(0, std::max(64, QThread::idealThreadCount()));
    renderThreads->setSpecialValueText(tr("All cores"));
    renderThreads->setValue(prefs_.renderThreads);
    connect(renderThreads, &QSpinBox::valueChanged, this, [=, this](int v) {
        prefs_.renderThreads = v;
        notify();
    });
    form->addRow(tr("Render Image threads"), renderThreads);

    // Same image either way (tested); Embree is faster on meshes and large scenes, the
    // built-in one is the thesis's own BVH with refit.
    auto* engine =
        enumCombo(this, "engine", {tr("Embree"), tr("Built-in BVH (thesis)")}, prefs_.engine);
    connect(engine, &QComboBox::currentIndexChanged, this, [=, this](int i) {
        prefs_.engine = EngineKind(i);
        notify();
    });
    form->addRow(tr("Ray engine"), engine);
}

void PreferencesDialog::addKeepingRows(QFormLayout* form) {
    auto* autosave = new QSpinBox(this);
    autosave->setObjectName(QStringLiteral("autosaveSeconds"));
    autosave->setRange(0, 24 * 3600);
    autosave->setSuffix(tr(" s"));
    autosave->setSpecialValueText(tr("Off"));
    autosave->setValue(prefs_.autosaveSeconds);
    connect(autosave, &QSpinBox::valueChanged, this, [=, this](int v) {
        prefs_.autosaveSeconds = v;
        notify();
    });
    form->addRow(tr("Autosave every"), autosave);

    // Decoded texture tiles kept in memory (OpenImageIO's cache), for the whole process.
    auto* textureCache = new QSpinBox(this);
    textureCache->setObjectName(QStringLiteral("textureCacheMegabytes"));
    textureCache->setRange(kMinTextureCacheMegabytes, kMaxTextureCacheMegabytes);
    textureCache->setSingleStep(64);
    textureCache->setKeyboardTracking(false);
    textureCache->setValue(prefs_.textureCacheMegabytes);
    textureCache->setToolTip(
        tr("Memory for decoded image textures and environments (default %1 MB); more keeps "
           "large textures from being read again")
            .arg(int(kDefaultTextureCacheMegabytes)));
    connect(textureCache, &QSpinBox::valueChanged, this, [=, this](int v) {
        prefs_.textureCacheMegabytes = v;
        applyProcessPreferences(prefs_);
        notify();
    });
    form->addRow(tr("Texture cache (MB)"), textureCache);
}

}  // namespace rs::ui
