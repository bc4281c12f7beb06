// Finding an entry by its id in a list that is normally in id order.
#pragma once

#include <algorithm>
#include <cstddef>

namespace rs {

/// The index of the entry of `list` whose id (`idOf(entry)`) is `id`, or -1. Ids are handed
/// out in increasing order and lists are appended to and erased from, so they are normally
/// sorted by id and a binary search finds the entry in O(log n) (a linear search per object
/// per edit made moving one of 10,000 objects quadratic); a list in another order is then
/// searched whole, so the answer never depends on the order, only the speed.
template <class List, class Id, class IdOf>
std::ptrdiff_t indexById(const List& list, Id id, IdOf idOf) {
    const auto first = std::begin(list), last = std::end(list);
    auto it =
        std::lower_bound(first, last, id, [&](const auto& e, Id key) { return idOf(e) < key; });
    if (it == last || idOf(*it) != id)
        it = std::find_if(first, last, [&](const auto& e) { return idOf(e) == id; });
    return it == last ? -1 : std::ptrdiff_t(it - first);
}

}  // namespace rs
