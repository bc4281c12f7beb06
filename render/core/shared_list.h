// A list whose copies share unchanged chunks: copying it copies a pointer per chunk, and a
// write copies only the chunk it lands in. Documents, undo steps and the session's copies of
// a 100,000-object scene then cost what an edit changes, not what the scene holds (as
// Blender's undo shares the unchanged chunks of its memory file between steps).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rs {

/// A sequence of T in chunks of kChunk elements (all full but the last), each shared between
/// copies until one of them writes to it. Reading is as a const std::vector's (random-access
/// const iterators, operator[]); writing goes through the non-const operator[], front(),
/// back(), editable(), push_back(), insert() and erase(), which copy a shared chunk first.
///
/// A reference from a non-const accessor is valid until the list is next changed or copied:
/// a copy shares the chunk the reference points into, so writing through an old reference
/// after a copy would change both lists. Take references after copying, as edits do.
///
/// Chunks carry their own reference count, loaded with acquire ordering before a write in
/// place, so a list on one thread may write a chunk that another thread has just let go of.
template <class T>
class SharedList {
public:
    static constexpr std::size_t kChunkBits = 7;
    static constexpr std::size_t kChunk = std::size_t(1) << kChunkBits;

    class const_iterator {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = T;
        using difference_type = std::ptrdiff_t;
        using pointer = const T*;
        using reference = const T&;
        const_iterator() = default;
        const_iterator(const SharedList* list, std::size_t i) : list_(list), i_(i) {}
        const T& operator*() const { return (*list_)[i_]; }
        const T* operator->() const { return &(*list_)[i_]; }
        const T& operator[](difference_type n) const { return (*list_)[i_ + n]; }
        const_iterator& operator++() { return ++i_, *this; }
        const_iterator operator++(int) { return {list_, i_++}; }
        const_iterator& operator--() { return --i_, *this; }
        const_iterator operator--(int) { return {list_, i_--}; }
        const_iterator& operator+=(difference_type n) { return i_ += n, *this; }
        const_iterator& operator-=(difference_type n) { return i_ -= n, *this; }
        friend const_iterator operator+(const_iterator a, difference_type n) { return a += n; }
        friend const_iterator operator+(difference_type n, const_iterator a) { return a += n; }
        friend const_iterator operator-(const_iterator a, difference_type n) { return a -= n; }
        friend difference_type operator-(const const_iterator& a, const const_iterator& b) {
            return difference_type(a.i_) - difference_type(b.i_);
        }
        friend bool operator==(const const_iterator& a, const const_iterator& b) {
            return a.i_ == b.i_;
        }
        friend auto operator<=>(const const_iterator& a, const const_iterator& b) {
            return a.i_ <=> b.i_;
        }
        std::size_t index() const { return i_; }

    private:
        const SharedList* list_ = nullptr;
        std::size_t i_ = 0;
    };
    using iterator = const_iterator;  // Elements change through the writing accessors only.
    using value_type = T;
    using size_type = std::size_t;

    /// Every element, each written through operator[] (a chunk is copied once, when shared).
    class Editable {
    public:
        class iterator {
        public:
            iterator(SharedList* list, std::size_t i) : list_(list), i_(i) {}
            T& operator*() const { return (*list_)[i_]; }
            iterator& operator++() { return ++i_, *this; }
            bool operator==(const iterator& o) const { return i_ == o.i_; }

        private:
            SharedList* list_;
            std::size_t i_;
        };
        explicit Editable(SharedList* list) : list_(list) {}
        iterator begin() const { return {list_, 0}; }
        iterator end() const { return {list_, list_->size()}; }

    private:
        SharedList* list_;
    };

    SharedList() = default;
    SharedList(std::initializer_list<T> items) { assign(items.begin(), items.end()); }
    explicit SharedList(const std::vector<T>& items) { assign(items.begin(), items.end()); }
    SharedList(const SharedList& o) : chunks_(o.chunks_), size_(o.size_) {
        for (Chunk* c : chunks_) c->retain();
    }
    SharedList(SharedList&& o) noexcept
        : chunks_(std::exchange(o.chunks_, {})), size_(std::exchange(o.size_, 0)) {}
    SharedList& operator=(const SharedList& o) {
        if (this != &o) {
            SharedList copy(o);
            swap(copy);
        }
        return *this;
    }
    SharedList& operator=(SharedList&& o) noexcept {
        SharedList gone(std::move(o));
        swap(gone);
        return *this;
    }
    ~SharedList() { releaseAll(); }
    void swap(SharedList& o) noexcept {
        chunks_.swap(o.chunks_);
        std::swap(size_, o.size_);
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const T& operator[](std::size_t i) const {
        return chunks_[i >> kChunkBits]->items[i & (kChunk - 1)];
    }
    T& operator[](std::size_t i) { return owned(i >> kChunkBits).items[i & (kChunk - 1)]; }
    const T& at(std::size_t i) const {
        if (i >= size_) throw std::out_of_range("SharedList::at: index out of range");
        return (*this)[i];
    }
    T& at(std::size_t i) {
        if (i >= size_) throw std::out_of_range("SharedList::at: index out of range");
        return (*this)[i];
    }
    const T& front() const { return (*this)[0]; }
    const T& back() const { return (*this)[size_ - 1]; }
    T& front() { return (*this)[0]; }
    T& back() { return (*this)[size_ - 1]; }
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size_}; }
    const_iterator cbegin() const { return begin(); }
    const_iterator cend() const { return end(); }
    /// A range over every element for writing: `for (T& e : list.editable())`.
    Editable editable() { return Editable(this); }

    void push_back(T value) {
        if (size_ % kChunk == 0) {
            chunks_.push_back(new Chunk);
            chunks_.back()->items.reserve(kChunk);
        }
        owned(chunks_.size() - 1).items.push_back(std::move(value));
        ++size_;
    }
    void pop_back() {
        owned(chunks_.size() - 1).items.pop_back();
        if (--size_ % kChunk == 0) {
            if (chunks_.back()->release()) delete chunks_.back();
            chunks_.pop_back();
        }
    }
    void clear() {
        releaseAll();
        size_ = 0;
    }
    void reserve(std::size_t) {}
    template <class It>
    void assign(It first, It last) {
        clear();
        for (; first != last; ++first) push_back(*first);
    }
    const_iterator insert(const_iterator pos, T value) {
        const std::size_t at = pos.index();
        std::vector<T> tail = takeFrom(at);
        push_back(std::move(value));
        for (T& e : tail) push_back(std::move(e));
        return {this, at};
    }
    const_iterator erase(const_iterator pos) { return erase(pos, pos + 1); }
    const_iterator erase(const_iterator first, const_iterator last) {
        const std::size_t at = first.index(), n = std::size_t(last - first);
        std::vector<T> tail = takeFrom(at);
        for (std::size_t i = n; i < tail.size(); ++i) push_back(std::move(tail[i]));
        return {this, at};
    }
    /// Removes the elements `pred` holds for; returns how many. Chunks before the first such
    /// element stay shared.
    template <class Pred>
    std::size_t eraseIf(Pred pred) {
        const auto first = std::find_if(begin(), end(), pred);
        if (first == end()) return 0;
        std::vector<T> tail = takeFrom(first.index());
        std::size_t removed = 0;
        for (T& e : tail) {
            if (pred(std::as_const(e)))
                ++removed;
            else
                push_back(std::move(e));
        }
        return removed;
    }
    std::vector<T> toVector() const { return std::vector<T>(begin(), end()); }

    /// Number of chunks, and whether chunk `c` of this list and of `o` is one and the same
    /// (then their elements [c * kChunk, ...) are equal, without looking at them).
    std::size_t chunkCount() const { return chunks_.size(); }
    bool sharesChunk(const SharedList& o, std::size_t c) const {
        return c < chunks_.size() && c < o.chunks_.size() && chunks_[c] == o.chunks_[c];
    }

    friend bool operator==(const SharedList& a, const SharedList& b) {
        if (a.size_ != b.size_) return false;
        for (std::size_t c = 0; c < a.chunks_.size(); ++c)
            if (a.chunks_[c] != b.chunks_[c] && !(a.chunks_[c]->items == b.chunks_[c]->items))
                return false;
        return true;
    }

private:
    struct Chunk {
        std::atomic<int> refs{1};
        std::vector<T> items;
        void retain() { refs.fetch_add(1, std::memory_order_relaxed); }
        /// True when this was the last reference (the caller deletes the chunk).
        bool release() { return refs.fetch_sub(1, std::memory_order_acq_rel) == 1; }
        bool unique() const { return refs.load(std::memory_order_acquire) == 1; }
    };

    /// Chunk `c`, copied first when another list shares it.
    Chunk& owned(std::size_t c) {
        Chunk*& chunk = chunks_[c];
        if (!chunk->unique()) {
            auto* copy = new Chunk;
            copy->items.reserve(kChunk);
            copy->items = chunk->items;
            if (chunk->release()) delete chunk;
            chunk = copy;
        }
        return *chunk;
    }
    /// Removes and returns the elements from index `at` on; chunks before it stay as they are.
    /// Elements of chunks no other list shares are moved, the others copied.
    std::vector<T> takeFrom(std::size_t at) {
        std::vector<T> tail;
        tail.reserve(size_ - at);
        const std::size_t firstChunk = at >> kChunkBits;
        const auto take = [](Chunk& chunk, std::size_t from, std::size_t to, std::vector<T>& out) {
            const auto first = chunk.items.begin() + std::ptrdiff_t(from);
            const auto last = chunk.items.begin() + std::ptrdiff_t(to);
            if (chunk.unique())
                out.insert(out.end(), std::make_move_iterator(first),
                           std::make_move_iterator(last));
            else
                out.insert(out.end(), first, last);
        };
        for (std::size_t c = firstChunk; c < chunks_.size(); ++c) {
            Chunk& chunk = *chunks_[c];
            take(chunk, c == firstChunk ? (at & (kChunk - 1)) : 0, chunk.items.size(), tail);
        }
        std::vector<T> head;
        if (at & (kChunk - 1)) take(*chunks_[firstChunk], 0, at & (kChunk - 1), head);
        for (std::size_t c = firstChunk; c < chunks_.size(); ++c)
            if (chunks_[c]->release()) delete chunks_[c];
        chunks_.resize(firstChunk);
        size_ = firstChunk * kChunk;
        for (T& e : head) push_back(std::move(e));
        return tail;
    }
    void releaseAll() {
        for (Chunk* c : chunks_)
            if (c->release()) delete c;
        chunks_.clear();
    }

    std::vector<Chunk*> chunks_;
    std::size_t size_ = 0;
};

}  // namespace rs
