// What one edit changed between two documents: the parts, and the objects with their fields.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/document.h"

namespace rs {

/// The difference between two documents, as the undo stack, the session and the panels need
/// it. Found in time proportional to what changed, because a document and its edited copy
/// share every chunk of objects the edit left alone (SharedList).
struct DocumentChange {
    /// Which fields of an object changed.
    enum Field : uint8_t {
        kShape = 1,     ///< Geometry or transform.
        kMaterial = 2,  ///< Its material's name.
        kName = 4,      ///< Its name.
        kVisible = 8,   ///< Shown or hidden.
        kExtras = 16,   ///< `x-` keys.
    };
    struct ObjectEdit {
        ObjectId id;
        std::size_t index;  ///< Its place in both documents' object lists.
        uint8_t fields;     ///< Field bits.
    };

    bool camera = false;
    bool render = false;
    bool materials = false;
    bool lights = false;
    bool environment = false;
    bool views = false;  ///< The view bookmarks: nothing a render shows.
    bool extras = false;
    /// Objects were added, removed or reordered: `objects` is empty and says nothing then.
    bool objectsRestructured = false;
    /// Objects that kept their id and place but changed, in document order.
    std::vector<ObjectEdit> objects;

    /// A change of everything (a document opened): what a listener assumes without a diff.
    static DocumentChange everything();
    bool any() const {
        return camera || render || materials || lights || environment || views || extras ||
               objectsRestructured || !objects.empty();
    }
    /// The union of the changed objects' field bits.
    uint8_t objectFields() const;
};

/// What changed from `before` to `after`. Objects are compared chunk by chunk, and chunks the
/// two documents share are skipped without looking at them.
DocumentChange describeChange(const SceneDocument& before, const SceneDocument& after);

}  // namespace rs
