// Line/column positions inside JSON text, because nlohmann's DOM forgets where values were.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace rs {

/// A 1-based line and column (columns count UTF-8 code points); 0 means unknown.
struct TextPosition {
    int line = 0;
    int column = 0;
};

/// Position of a byte offset in `text` (offsets past the end give the end of the text).
TextPosition positionOfOffset(std::string_view text, std::size_t offset);

/// Appends one JSON pointer segment to `pointer`, escaping '~' and '/' (RFC 6901).
std::string appendPointer(const std::string& pointer, std::string_view segment);
/// Appends an array index segment to `pointer`.
std::string appendPointer(const std::string& pointer, std::size_t index);

/// Index of where every value and member key of a syntactically valid JSON text starts.
/// Built once per text with a minimal tokenizer; look-ups are by JSON pointer.
class JsonLocator {
public:
    /// Deeper nesting is not indexed (and reported through tooDeep()) to bound recursion.
    static constexpr int kMaxDepth = 200;

    explicit JsonLocator(std::string_view text);

    /// Where the value at `pointer` starts; for a pointer that does not exist (a missing
    /// key), where the nearest existing enclosing value starts.
    TextPosition valuePosition(const std::string& pointer) const;
    /// Where the member's key starts (array elements: the value); falls back like valuePosition.
    TextPosition keyPosition(const std::string& pointer) const;
    /// A key that repeats an earlier key of the same object, and where the repeat is.
    struct DuplicateKey {
        std::string pointer;
        TextPosition position;
    };
    /// Every repeated key (second occurrence on), in text order.
    const std::vector<DuplicateKey>& duplicateKeys() const { return duplicates_; }
    /// True when the text nests deeper than kMaxDepth.
    bool tooDeep() const { return tooDeep_; }

private:
    struct Entry {
        TextPosition key;
        TextPosition value;
    };
    class Tokenizer;
    const Entry* find(const std::string& pointer) const;

    std::unordered_map<std::string, Entry> entries_;
    std::vector<DuplicateKey> duplicates_;
    bool tooDeep_ = false;
};

}  // namespace rs
