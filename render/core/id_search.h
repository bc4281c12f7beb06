// Finding an entry by its id in a list kept in increasing id order.
#pragma once

#include <algorithm>
#include <cstddef>

namespace rs {

/// The index of the entry of `list` whose id (`idOf(entry)`) is `id`, or -1, in O(log n).
/// `list` must be in increasing id order, as a document's objects and lights are (ids are
/// handed out in increasing order, entries are only appended and erased) and as what follows
/// them is (compiled primitives, outliner rows). A linear search per object per edit made
/// moving one of 10,000 objects quadratic; a linear search after every miss (a light's id, no
/// selection) scanned all 100,000 objects of a scene per property-panel refresh.
template <class List, class Id, class IdOf>
std::ptrdiff_t indexById(const List& list, Id id, IdOf idOf) {
    const auto first = std::begin(list), last = std::end(list);
    const auto it =
        std::lower_bound(first, last, id, [&](const auto& e, Id key) { return idOf(e) < key; });
    return it == last || idOf(*it) != id ? -1 : std::ptrdiff_t(it - first);
}

}  // namespace rs
