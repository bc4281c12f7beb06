// A minimal JSON tokenizer that records where each value starts, keyed by JSON pointer.
#include "io/json_location.h"

#include <cstdint>
#include <unordered_set>

namespace rs {

namespace {
bool isContinuationByte(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

void appendUtf8(std::string& out, uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}
}  // namespace

TextPosition positionOfOffset(std::string_view text, std::size_t offset) {
    TextPosition pos{1, 1};
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++pos.line;
            pos.column = 1;
        } else if (!isContinuationByte(text[i])) {
            ++pos.column;
        }
    }
    return pos;
}

std::string appendPointer(const std::string& pointer, std::string_view segment) {
    std::string out = pointer + '/';
    for (char c : segment) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string appendPointer(const std::string& pointer, std::size_t index) {
    return pointer + '/' + std::to_string(index);
}

// Walks text that nlohmann already accepted; on anything unexpected it simply stops, so a
// bug here costs positions in messages, never a crash or a wrong verdict on the file.
class JsonLocator::Tokenizer {
public:
    Tokenizer(std::string_view text, JsonLocator& out) : t_(text), out_(out) {
        if (t_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // nlohmann skips a UTF-8 BOM too
    }

    void run() {
        skipSpace();
        value("", here(), here(), 0);
    }

private:
    TextPosition here() const { return {line_, column_}; }
    bool atEnd() const { return i_ >= t_.size(); }
    char peek() const { return atEnd() ? '\0' : t_[i_]; }

    void advance() {
        if (atEnd()) return;
        if (t_[i_] == '\n') {
            ++line_;
            column_ = 1;
        } else if (!isContinuationByte(t_[i_])) {
            ++column_;
        }
        ++i_;
    }

    void skipSpace() {
        while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r'))
            advance();
    }

    bool value(const std::string& pointer, TextPosition keyPos, TextPosition valuePos, int depth) {
        out_.entries_.emplace(pointer, Entry{keyPos, valuePos});
        char c = peek();
        if (c == '{' || c == '[') {
            if (depth >= kMaxDepth) {
                out_.tooDeep_ = true;
                return false;
            }
            return c == '{' ? object(pointer, depth) : array(pointer, depth);
        }
        if (c == '"') return string(nullptr);
        // Numbers and literals: everything up to the next structural character or space.
        while (!atEnd() && peek() != ',' && peek() != '}' && peek() != ']' && peek() != ' ' &&
               peek() != '\t' && peek() != '\n' && peek() != '\r')
            advance();
        return true;
    }

    bool object(const std::string& pointer, int depth) {
        advance();  // '{'
        std::unordered_set<std::string> seen;
        skipSpace();
        if (peek() == '}') {
            advance();
            return true;
        }
        for (;;) {
            skipSpace();
            TextPosition keyPos = here();
            std::string key;
            if (peek() != '"' || !string(&key)) return false;
            std::string member = appendPointer(pointer, key);
            if (!seen.insert(key).second) out_.duplicates_.push_back({member, keyPos});
            skipSpace();
            if (peek() != ':') return false;
            advance();
            skipSpace();
            if (!value(member, keyPos, here(), depth + 1)) return false;
            skipSpace();
            if (peek() == ',') {
                advance();
                continue;
            }
            if (peek() != '}') return false;
            advance();
            return true;
        }
    }

    bool array(const std::string& pointer, int depth) {
        advance();  // '['
        skipSpace();
        if (peek() == ']') {
            advance();
            return true;
        }
        for (std::size_t index = 0;; ++index) {
            skipSpace();
            TextPosition pos = here();
            if (!value(appendPointer(pointer, index), pos, pos, depth + 1)) return false;
            skipSpace();
            if (peek() == ',') {
                advance();
                continue;
            }
            if (peek() != ']') return false;
            advance();
            return true;
        }
    }

    // Reads a string token; decodes it into `decoded` when given (keys, for the pointer).
    bool string(std::string* decoded) {
        advance();  // opening quote
        while (!atEnd()) {
            char c = peek();
            if (c == '"') {
                advance();
                return true;
            }
            if (c != '\\') {
                if (decoded) *decoded += c;
                advance();
                continue;
            }
            advance();
            char e = peek();
            advance();
            if (e == 'u') {
                uint32_t cp = hex4();
                if (cp >= 0xD800 && cp < 0xDC00 && peek() == '\\') {
                    advance();
                    advance();  // 'u' of the low surrogate
                    uint32_t low = hex4();
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                }
                if (decoded) appendUtf8(*decoded, cp);
            } else if (decoded) {
                switch (e) {
                    case 'b':
                        *decoded += '\b';
                        break;
                    case 'f':
                        *decoded += '\f';
                        break;
                    case 'n':
                        *decoded += '\n';
                        break;
                    case 'r':
                        *decoded += '\r';
                        break;
                    case 't':
                        *decoded += '\t';
                        break;
                    default:
                        *decoded += e;
                        break;  // '"', '\\', '/'
                }
            }
        }
        return false;
    }

    uint32_t hex4() {
        uint32_t v = 0;
        for (int k = 0; k < 4 && !atEnd(); ++k) {
            char c = peek();
            v <<= 4;
            if (c >= '0' && c <= '9')
                v |= static_cast<uint32_t>(c - '0');
            else if (c >= 'a' && c <= 'f')
                v |= static_cast<uint32_t>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F')
                v |= static_cast<uint32_t>(c - 'A' + 10);
            advance();
        }
        return v;
    }

    std::string_view t_;
    JsonLocator& out_;
    std::size_t i_ = 0;
    int line_ = 1;
    int column_ = 1;
};

JsonLocator::JsonLocator(std::string_view text) {
    Tokenizer(text, *this).run();
}

const JsonLocator::Entry* JsonLocator::find(const std::string& pointer) const {
    std::string p = pointer;
    for (;;) {
        auto it = entries_.find(p);
        if (it != entries_.end()) return &it->second;
        if (p.empty()) return nullptr;
        std::size_t slash = p.rfind('/');
        p.erase(slash == std::string::npos ? 0 : slash);
    }
}

TextPosition JsonLocator::valuePosition(const std::string& pointer) const {
    const Entry* e = find(pointer);
    return e ? e->value : TextPosition{};
}

TextPosition JsonLocator::keyPosition(const std::string& pointer) const {
    const Entry* e = find(pointer);
    return e ? e->key : TextPosition{};
}

}  // namespace rs
