// What the held mouse button does in the viewport, from press to release.
#pragma once

#include <QPoint>
#include <QRect>
#include <optional>

#include "viewport/object_drag.h"
#include "viewport/orbit.h"

namespace rs::ui {

/// The viewport's mouse drag: a press that has not yet moved past the threshold (on an
/// entity, or on empty space), then moving objects, orbiting, panning or drawing a selection
/// box; plus B's arming of the next left drag as a box. An object drag has its ObjectDrag and
/// an orbit its Orbit exactly while it runs.
class MouseDrag {
public:
    enum class Kind { None, PendingObject, Object, Orbit, Pan, PendingBox, Box };
    /// How far (Manhattan, widget pixels) a press moves before it is a drag, not a click.
    static constexpr int kThresholdPx = 3;

    Kind kind() const { return kind_; }
    /// A button is held over the viewport (or a press is pending).
    bool active() const { return kind_ != Kind::None; }
    /// Moving objects, orbiting or panning: the session runs its interaction policies.
    bool interacting() const {
        return kind_ == Kind::Object || kind_ == Kind::Orbit || kind_ == Kind::Pan;
    }

    /// A button went down at `pos`.
    void press(const QPoint& pos) { pressPos_ = lastPos_ = pos; }
    /// The cursor is at `pos` (a move, or where a gesture starts); returns how far it moved
    /// since it was last seen.
    QPoint moveTo(const QPoint& pos) {
        const QPoint delta = pos - lastPos_;
        lastPos_ = pos;
        return delta;
    }
    const QPoint& pressPos() const { return pressPos_; }
    const QPoint& lastPos() const { return lastPos_; }
    /// The cursor has left the press point by the threshold: a drag, not a click.
    bool pastThreshold() const { return (lastPos_ - pressPos_).manhattanLength() >= kThresholdPx; }
    /// The selection box from the press to the cursor.
    QRect box() const { return QRect(pressPos_, lastPos_).normalized(); }

    /// Pressed on `id`: a drag moves it (and the selection), a click selects it.
    void pressEntity(ObjectId id) {
        kind_ = Kind::PendingObject;
        pressed_ = id;
    }
    /// The entity of the last pressEntity().
    ObjectId pressedEntity() const { return pressed_; }
    /// Pressed on empty space: a drag draws a box, a click clears the selection.
    void pressEmpty() { kind_ = Kind::PendingBox; }
    void startBox() { kind_ = Kind::Box; }
    void startPan() { kind_ = Kind::Pan; }
    void startOrbit(Orbit orbit) {
        kind_ = Kind::Orbit;
        orbit_.emplace(std::move(orbit));
    }
    void startObjects(ObjectDrag objects) {
        kind_ = Kind::Object;
        objects_.emplace(std::move(objects));
    }
    /// The running orbit, or null.
    Orbit* orbit() { return orbit_ ? &*orbit_ : nullptr; }
    /// The running object drag, or null.
    ObjectDrag* objects() { return objects_ ? &*objects_ : nullptr; }
    /// Ends the drag (or the press); returns the object drag it ran, if any.
    std::optional<ObjectDrag> finish();

    /// B: the next left drag draws a box, even over an object.
    void armBox() { boxArmed_ = true; }
    void disarmBox() { boxArmed_ = false; }
    bool boxArmed() const { return boxArmed_; }

private:
    Kind kind_ = Kind::None;
    QPoint pressPos_, lastPos_;
    ObjectId pressed_ = kNoObject;  ///< The entity pressed.
    bool boxArmed_ = false;
    std::optional<ObjectDrag> objects_;
    std::optional<Orbit> orbit_;
};

}  // namespace rs::ui
