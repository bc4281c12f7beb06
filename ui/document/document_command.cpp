// Whole-document before/after commands: simple, and robust against any kind of edit.
#include "document/document_command.h"

namespace rs::ui {

DocumentCommand::DocumentCommand(SceneEditor* editor, const QString& text, SceneDocument before,
                                 SceneDocument after, MergeKind merge, QString mergeKey, int serial)
    : QUndoCommand(text),
      editor_(editor),
      before_(std::move(before)),
      after_(std::move(after)),
      merge_(merge),
      mergeKey_(std::move(mergeKey)),
      serial_(serial) {}

void DocumentCommand::undo() {
    editor_->replaceDocument(before_);
}

void DocumentCommand::redo() {
    editor_->replaceDocument(after_);
}

bool DocumentCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = dynamic_cast<const DocumentCommand*>(other);
    if (!o || merge_ == MergeKind::None || o->merge_ != merge_ || o->mergeKey_ != mergeKey_ ||
        o->serial_ != serial_)
        return false;
    after_ = o->after_;
    // A drag cancelled back to where it began leaves nothing to undo.
    if (after_.sameContent(before_)) setObsolete(true);
    return true;
}

}  // namespace rs::ui
