// Render -> Submit to Cluster...: the options of `raystudio-cli farm submit`, run through that
// very command (the designer writes no job scripts of its own), with where the result appears.
#pragma once

#include <QDialog>
#include <QString>
#include <QStringList>

class QLabel;
class QLineEdit;
class QProcess;
class QPushButton;
class QSpinBox;

namespace rs::ui {

/// True when Slurm's sbatch is on PATH (the menu entry is offered only then).
bool clusterSubmitAvailable();

/// raystudio-cli next to the running designer (build tree and installed layout alike), else
/// the one on PATH.
QString farmCliPath();

/// Non-modal dialog: output image, parts, partition, time limit and size; Submit runs
/// `raystudio-cli farm submit` in the background and shows the job ids it printed (or its
/// error) and where the merged image will appear.
class ClusterSubmitDialog : public QDialog {
    Q_OBJECT
public:
    /// For the saved scene file `scenePath`, at its render size width x height.
    ClusterSubmitDialog(const QString& scenePath, int width, int height, QWidget* parent = nullptr);
    ~ClusterSubmitDialog() override;

    /// The command's arguments the fields give, from "farm" on.
    QStringList arguments() const;
    /// Starts the submission (the Submit button).
    void submit();
    /// What the last submission printed, or its error; empty before one finished.
    QString resultText() const;

Q_SIGNALS:
    /// The command finished: ok when it exited 0.
    void submissionFinished(bool ok);

private:
    void updateNote();

    QString scenePath_;
    QLineEdit* output_;
    QSpinBox* parts_;
    QLineEdit* partition_;
    QLineEdit* time_;
    QSpinBox* width_;
    QSpinBox* height_;
    QLabel* note_;
    QLabel* result_;
    QPushButton* submit_;
    QProcess* process_ = nullptr;
};

}  // namespace rs::ui
