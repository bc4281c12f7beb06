// The Submit to Cluster dialog: fields, the farm submit process and its answer.
#include "jobs/cluster_submit_dialog.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>

#include "image/image_part.h"
#include "scene/document.h"

namespace rs::ui {

bool clusterSubmitAvailable() {
    return !QStandardPaths::findExecutable("sbatch").isEmpty();
}

QString farmCliPath() {
    const QString beside = QDir(QCoreApplication::applicationDirPath()).filePath("raystudio-cli");
    if (QFileInfo(beside).isExecutable()) return beside;
    const QString onPath = QStandardPaths::findExecutable("raystudio-cli");
    return onPath.isEmpty() ? beside : onPath;
}

ClusterSubmitDialog::ClusterSubmitDialog(const QString& scenePath, int width, int height,
                                         QWidget* parent)
    : QDialog(parent), scenePath_(scenePath) {
    setWindowTitle(tr("Submit to Cluster"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("Scene"), new QLabel(QDir::toNativeSeparators(scenePath), this));

    const QFileInfo scene(scenePath);
    output_ = new QLineEdit(
        scene.dir().filePath(scene.completeBaseName().remove(".scene") + ".exr"), this);
    output_->setObjectName("clusterOutput");
    auto* browse = new QPushButton(tr("Browse..."), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Merged Image"), output_->text(),
            tr("Images (*.exr *.png *.jpg *.jpeg *.tif *.tiff *.hdr)"));
        if (!path.isEmpty()) output_->setText(path);
    });
    auto* outputRow = new QHBoxLayout;
    outputRow->addWidget(output_);
    outputRow->addWidget(browse);
    form->addRow(tr("Output"), outputRow);

    parts_ = new QSpinBox(this);
    parts_->setObjectName("clusterParts");
    parts_->setRange(1, kMaxImageParts);
    parts_->setValue(4);
    form->addRow(tr("Parts (job array tasks)"), parts_);
    partition_ = new QLineEdit(this);
    partition_->setObjectName("clusterPartition");
    partition_->setPlaceholderText(tr("cluster default"));
    form->addRow(tr("Partition"), partition_);
    time_ = new QLineEdit(this);
    time_->setObjectName("clusterTime");
    time_->setPlaceholderText(tr("partition default, e.g. 1:00:00"));
    form->addRow(tr("Time limit per task"), time_);
    width_ = new QSpinBox(this);
    height_ = new QSpinBox(this);
    width_->setRange(1, kMaxImageSide);
    height_->setRange(1, kMaxImageSide);
    width_->setValue(width);
    height_->setValue(height);
    form->addRow(tr("Width"), width_);
    form->addRow(tr("Height"), height_);

    note_ = new QLabel(this);
    note_->setObjectName("clusterNote");
    note_->setWordWrap(true);
    form->addRow(note_);
    result_ = new QLabel(this);
    result_->setObjectName("clusterResult");
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(result_);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    submit_ = buttons->addButton(tr("Submit"), QDialogButtonBox::AcceptRole);
    submit_->setObjectName("clusterSubmit");
    connect(submit_, &QPushButton::clicked, this, &ClusterSubmitDialog::submit);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
    connect(output_, &QLineEdit::textChanged, this, &ClusterSubmitDialog::updateNote);
    updateNote();
}

ClusterSubmitDialog::~ClusterSubmitDialog() {
    if (process_) process_->disconnect(this);  // a running sbatch finishes on its own
}

void ClusterSubmitDialog::updateNote() {
    const QString out = QDir::toNativeSeparators(QFileInfo(output_->text()).absoluteFilePath());
    note_->setText(tr("The nodes read the scene and its meshes and write the image through these "
                      "same paths: they must be on a file system every node sees. The merged image "
                      "appears at %1 when the merge job finishes; the parts, job scripts and logs "
                      "go to %1.parts/.")
                       .arg(out));
}

QStringList ClusterSubmitDialog::arguments() const {
    QStringList args{"farm",
                     "submit",
                     scenePath_,
                     "-o",
                     QFileInfo(output_->text()).absoluteFilePath(),
                     "--parts",
                     QString::number(parts_->value()),
                     "--width",
                     QString::number(width_->value()),
                     "--height",
                     QString::number(height_->value())};
    if (!partition_->text().trimmed().isEmpty())
        args << "--partition" << partition_->text().trimmed();
    if (!time_->text().trimmed().isEmpty()) args << "--time" << time_->text().trimmed();
    return args;
}

QString ClusterSubmitDialog::resultText() const {
    return result_->text();
}

void ClusterSubmitDialog::submit() {
    if (process_) return;  // one submission at a time
    submit_->setEnabled(false);
    result_->setText(tr("Submitting..."));
    process_ = new QProcess(this);
    process_->setProcessChannelMode(QProcess::SeparateChannels);
    connect(process_, &QProcess::finished, this, [this](int code, QProcess::ExitStatus status) {
        const QString out = QString::fromLocal8Bit(process_->readAllStandardOutput()).trimmed();
        const QString err = QString::fromLocal8Bit(process_->readAllStandardError()).trimmed();
        const bool ok = status == QProcess::NormalExit && code == 0;
        result_->setText(
            ok ? tr("Submitted:\n%1\nFollow it with: raystudio-cli farm status JOB").arg(out)
               : tr("Not submitted:\n%1").arg(err.isEmpty() ? tr("exit code %1").arg(code) : err));
        process_->deleteLater();
        process_ = nullptr;
        submit_->setEnabled(true);
        Q_EMIT submissionFinished(ok);
    });
    connect(process_, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error != QProcess::FailedToStart) return;
        result_->setText(tr("Not submitted: cannot start %1").arg(farmCliPath()));
        process_->deleteLater();
        process_ = nullptr;
        submit_->setEnabled(true);
        Q_EMIT submissionFinished(false);
    });
    process_->start(farmCliPath(), arguments());
}

}  // namespace rs::ui
