// OFF and PLY header counts against the file size, read from the head of the file only.
#include "io/mesh_header_check.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string_view>
#include <vector>

#include "core/input_file.h"

namespace rs {

namespace {

// A PLY header longer than this is not a real one (they are a few hundred bytes).
constexpr std::size_t kMaxHeaderBytes = std::size_t(1) << 20;

// In ASCII, a number takes at least one character and one separator.
constexpr std::uintmax_t kMinAsciiNumberBytes = 2;

std::string readHead(const std::string& path, std::size_t limit) {
    std::ifstream in(path, std::ios::binary);
    std::string head(limit, '\0');
    in.read(head.data(), static_cast<std::streamsize>(limit));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    return head;
}

std::optional<std::uintmax_t> parseCount(std::string_view token) {
    std::uintmax_t value = 0;
    const char* end = token.data() + token.size();
    auto [ptr, ec] = std::from_chars(token.data(), end, value);
    if (ec != std::errc() || ptr != end || token.empty()) return std::nullopt;
    return value;
}

// One kind of element the header declares: how many, and the least bytes each needs.
struct ElementClaim {
    std::string name;  ///< As messages count them: "vertices", "vertex elements".
    std::uintmax_t count = 0;
    std::uintmax_t minBytes = 1;
};

// Empty when `headerBytes` plus the claimed elements fit in `fileSize` (+ `slack` bytes).
std::string compareWithSize(const char* format, std::uintmax_t headerBytes,
                            const std::vector<ElementClaim>& claims, std::uintmax_t fileSize,
                            std::uintmax_t slack = 0) {
    // Compared by division, element by element, so no count can overflow the sum.
    const std::uintmax_t capacity = fileSize + slack;
    std::uintmax_t needed = std::min(headerBytes, capacity);
    bool fits = true;
    for (const ElementClaim& c : claims) {
        if (c.count > (capacity - needed) / c.minBytes) {
            fits = false;
            break;
        }
        needed += c.count * c.minBytes;
    }
    if (fits) return {};
    std::string counts;
    for (const ElementClaim& c : claims)
        counts += (counts.empty() ? "" : ", ") + std::to_string(c.count) + " " + c.name;
    return std::string(format) + " header declares " + counts + ", more than the file's " +
           describeByteCount(fileSize) + " can hold (refused before reading it)";
}

// The text assimp 5.2's OFF importer parses (Debian's 5.2.5, BaseImporter::TextFileToBuffer):
// the file with a UTF-8 byte order mark dropped, or byte-swapped in pairs (a UTF-16 BE mark)
// or in words (a UTF-32 BE mark): its conversions are thrown away, the swaps are not. Files
// under 8 bytes it refuses (empty here, which the caller treats as nothing to check).
std::string offImporterText(std::string_view head) {
    if (head.size() < 8) return {};
    std::string text(head);
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    if (byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) return text.substr(3);
    if (byte(0) == 0x00 && byte(1) == 0x00 && byte(2) == 0xFE && byte(3) == 0xFF)
        for (std::size_t i = 0; i + 4 <= text.size(); i += 4) {
            std::swap(text[i], text[i + 3]);
            std::swap(text[i + 1], text[i + 2]);
        }
    if (byte(0) == 0xFE && byte(1) == 0xFF && text.size() % 2 == 0)
        for (std::size_t i = 0; i + 2 <= text.size(); i += 2) std::swap(text[i], text[i + 1]);
    return text;
}

// A cursor over that text that moves as the importer's header parser does (OFFLoader.cpp's
// NextToken, ParsingUtils' SkipSpacesAndLineEnd/SkipLine and fast_atof's strtoul10), so the
// check reads the counts the importer allocates for, whatever bytes surround them. The text
// ends in the NUL the importer appends.
class OffCursor {
public:
    explicit OffCursor(std::string_view text) : t_(text) {}
    char at(std::size_t k = 0) const { return i_ + k < t_.size() ? t_[i_ + k] : '\0'; }
    /// Bytes from the cursor to the end, the appended NUL included (the importer's `end - car`).
    std::size_t left() const { return t_.size() + 1 - std::min(i_, t_.size() + 1); }
    std::size_t offset() const { return i_; }
    void skip(std::size_t n) { i_ += n; }
    /// Skips blanks, line ends and whole comment lines (a '#' where a token would start).
    void nextToken() {
        skipSpacesAndLineEnds();
        while (at() == '#' || at() == '\n' || at() == '\r') {
            while (at() != '\r' && at() != '\n' && at() != '\0') ++i_;
            while (at() == '\r' || at() == '\n') ++i_;
            skipSpacesAndLineEnds();
        }
    }
    /// The leading digits as an unsigned 32-bit value, wrapping as the importer's does;
    /// `overflowed` tells that the digits did not fit.
    uint32_t readCount(bool& overflowed) {
        uint64_t value = 0;
        overflowed = false;
        for (; at() >= '0' && at() <= '9'; ++i_) {
            value = value * 10 + uint64_t(at() - '0');
            if (value > UINT32_MAX) overflowed = true, value &= UINT32_MAX;
        }
        return uint32_t(value);
    }

private:
    void skipSpacesAndLineEnds() {
        while (at() == ' ' || at() == '\t' || at() == '\r' || at() == '\n') ++i_;
    }
    std::string_view t_;
    std::size_t i_ = 0;
};

// OFF: "[ST][C][N][4][n]OFF", for nOFF the dimension, then "vertices faces edges", read as the
// importer reads them: the prefix letters one after another, the keyword optional (without it
// the counts start at the first token, which must start with a digit), each count its leading
// digits. The importer allocates every vertex and face before it reads a line, then takes one
// line each, and a NUL ends its text: the lines from the counts on to the file's first NUL
// must hold them (a line is at least one byte and a line end, the last one may lack the end).
// `complete` says `text` is the whole file, so a NUL past it cannot be missed.
std::string checkOff(std::string_view text, std::uintmax_t fileSize, bool complete) {
    OffCursor car(text);
    car.nextToken();
    bool hasDimension = false;
    if (car.left() > 2 && car.at() == 'S' && car.at(1) == 'T') car.skip(2);
    if (car.left() > 1 && car.at() == 'C') car.skip(1);
    if (car.left() > 1 && car.at() == 'N') car.skip(1);
    if (car.left() > 1 && car.at() == '4') car.skip(1);
    if (car.left() > 1 && car.at() == 'n') car.skip(1), hasDimension = true;
    if (car.left() > 3 && car.at() == 'O' && car.at(1) == 'F' && car.at(2) == 'F') {
        car.skip(3);
        car.nextToken();
    } else {
        car.nextToken();
        if (car.left() <= 1 || car.at() < '0' || car.at() > '9') return {};  // it refuses
    }
    bool overflowed = false;
    if (hasDimension) {
        const uint32_t dimensions = car.readCount(overflowed);
        if (dimensions > 3 || overflowed) return {};  // the importer refuses more than 3
        car.nextToken();
    }
    // A count whose digits overflow is refused outright: the importer would wrap it.
    const auto readClaim = [&](const char* what, uint32_t& count) -> std::string {
        car.nextToken();
        const std::size_t at = car.offset();
        count = car.readCount(overflowed);
        if (!overflowed) return {};
        return std::string("OFF header declares a ") + what +
               " count too large to be read: " + std::string(text.substr(at, 32));
    };
    uint32_t vertices = 0, faces = 0;
    if (std::string why = readClaim("vertex", vertices); !why.empty()) return why;
    if (std::string why = readClaim("face", faces); !why.empty()) return why;
    car.nextToken();
    car.readCount(overflowed);  // the edge count, which the importer skips
    car.nextToken();
    if (vertices == 0 || faces == 0) return {};  // the importer refuses both
    const std::size_t body = std::min(car.offset(), text.size());
    const std::size_t nul = text.find('\0', body);
    if (nul == std::string_view::npos)
        return compareWithSize("OFF", body, {{"vertices", vertices, 2}, {"faces", faces, 2}},
                               complete ? text.size() : fileSize, 1);
    std::string why =
        compareWithSize("OFF", body, {{"vertices", vertices, 2}, {"faces", faces, 2}}, nul, 1);
    if (!why.empty())
        why += "; the importer stops reading at its NUL byte at offset " + std::to_string(nul);
    return why;
}

std::uintmax_t plyScalarBytes(std::string_view type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// PLY: "ply", "format ascii|binary_* 1.0", then elements and their properties.
std::string checkPly(std::string_view head, std::uintmax_t fileSize) {
    // The importer takes any file starting with its magic number ("ply2\n" too).
    if (head.substr(0, 3) != "ply" && head.substr(0, 3) != "PLY") return {};
    bool ascii = true;
    std::vector<ElementClaim> claims;
    std::size_t pos = 0;
    for (;;) {
        const std::size_t eol = head.find('\n', pos);
        // Debian's assimp (5.2) never returns from a header without its end (the fuzzer
        // found it): a missing end_header is refused here.
        if (eol == std::string_view::npos)
            return head.size() >= kMaxHeaderBytes
                       ? "PLY header is longer than " + describeByteCount(kMaxHeaderBytes)
                       : "PLY header has no end_header line";
        const std::vector<std::string_view> w = words(head.substr(pos, eol - pos));
        pos = eol + 1;
        if (w.empty()) continue;
        if (w[0] == "end_header") break;
        if (w[0] == "format" && w.size() >= 2) {
            ascii = w[1] == "ascii";
        } else if (w[0] == "element" && w.size() >= 3) {
            auto count = parseCount(w[2]);
            if (!count)
                return "PLY header declares an unreadable " + std::string(w[1]) +
                       " count: " + std::string(w[2]);
            claims.push_back({std::string(w[1]) + " elements", *count, 0});
        } else if (w[0] == "property" && !claims.empty()) {
            // A list costs at least its count; each scalar its size (ASCII: a number). A type
            // the check does not know still takes a byte: the importer reads on regardless
            // (a misspelt type once let a 2-billion-vertex claim run for minutes).
            // "property list" may end there: the count's type is then unknown (a byte).
            const bool list = w.size() >= 2 && w[1] == "list";
            const std::size_t type = list ? 2 : 1;
            const std::uintmax_t bytes = plyScalarBytes(w.size() > type ? w[type] : "");
            claims.back().minBytes +=
                ascii ? kMinAsciiNumberBytes : std::max<std::uintmax_t>(bytes, 1);
        }
    }
    // An element without properties still takes a line (ASCII) or is not worth allocating for.
    for (ElementClaim& c : claims) c.minBytes = std::max<std::uintmax_t>(c.minBytes, 1);
    // The last ASCII number may end the file without a separator.
    const std::uintmax_t slack = ascii ? 1 : 0;
    return compareWithSize("PLY", pos, claims, fileSize, slack);
}

}  // namespace

std::string checkMeshHeader(const std::string& path, std::uintmax_t fileSize) {
    const std::string head = readHead(path, kMaxHeaderBytes);
    if (std::string why = checkPly(head, fileSize); !why.empty()) return why;
    // assimp picks its importer by the extension: a file named *.off is read as OFF whatever
    // it holds. Another name reaches the OFF importer only by its signature, "off" in its
    // first three bytes (any case), when no importer claims the extension; such a file is
    // checked as OFF whatever its extension (an OBJ that starts so is no real OBJ).
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    std::string start = head.substr(0, 3);
    for (char& c : start) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".off" && start.find("off") == std::string::npos) return {};
    const std::string text = offImporterText(head);
    // A dropped byte order mark shortens the text the importer reads by as much.
    return checkOff(text, fileSize - (head.size() - text.size()), head.size() == fileSize);
}

}  // namespace rs
