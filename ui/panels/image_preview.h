// A preview of an image file for the designer's panels (a texture's thumbnail, the
// environment's strip): the image scaled into a box, or the sentence why it cannot be read,
// read off the GUI thread (panels/preview_reader.h).
#pragma once

#include <QSize>
#include <QString>
#include <QWidget>
#include <string>

#include "core/input_file.h"
#include "jobs/gui_mailbox.h"

class QLabel;

namespace rs::ui {

struct PreviewPixels;

class ImagePreview : public QWidget {
    Q_OBJECT
public:
    /// Shows images read at most `readSide` pixels on their larger side, scaled down to fit
    /// `box` when larger. The two labels are named `imageName` and `errorName` (for tests).
    ImagePreview(QSize box, int readSide, Qt::Alignment alignment, const QString& imageName,
                 const QString& errorName, QWidget* parent = nullptr);
    /// Shows `path` (empty: nothing). The renderer's own check comes first, so the error is
    /// the one a render would report. Read again only when the file changed on disk; a file
    /// not read yet says so until its preview arrives from the reader's thread.
    void setImage(const std::string& path);
    /// The error shown (empty while an image, nothing, or the reading note is shown).
    QString error() const;
    /// True while an image (not an error) is shown.
    bool hasImage() const;
    /// True from setImage of a file not read yet until its preview (or error) is shown.
    bool reading() const { return reading_; }

private:
    /// Shows `preview` of shown_ (null: nothing) in place of what was shown.
    void display(const PreviewPixels* preview);

    QSize box_;
    int readSide_;
    QLabel* image_;
    QLabel* error_;
    QLabel* note_;
    std::string shown_;
    FileStamp shownStamp_;
    bool reading_ = false;
    GuiMailbox mailbox_{this};
};

}  // namespace rs::ui
