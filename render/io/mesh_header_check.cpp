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

#include "io/input_file.h"

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

// The value of `token`'s leading digits (0 when there are none); nullopt when it overflows.
std::optional<std::uintmax_t> parseLeadingCount(std::string_view token) {
    std::uintmax_t value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec == std::errc::result_out_of_range) return std::nullopt;
    return ptr == token.data() ? 0 : value;
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

// Splits ASCII header text into tokens, skipping '#' comments (OFF).
class OffTokens {
public:
    explicit OffTokens(std::string_view text) : t_(text) {}
    std::optional<std::string_view> next() {
        for (;;) {
            while (i_ < t_.size() && isSpace(t_[i_])) ++i_;
            if (i_ < t_.size() && t_[i_] == '#') {
                while (i_ < t_.size() && t_[i_] != '\n') ++i_;
                continue;
            }
            break;
        }
        if (i_ >= t_.size()) return std::nullopt;
        const std::size_t start = i_;
        while (i_ < t_.size() && !isSpace(t_[i_]) && t_[i_] != '#') ++i_;
        return t_.substr(start, i_ - start);
    }
    std::size_t offset() const { return i_; }

private:
    static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
    std::string_view t_;
    std::size_t i_ = 0;
};

// The vertex and face counts from `token` on, against the file size.
std::string checkOffCounts(OffTokens& tokens, std::string_view token, std::uintmax_t coordinates,
                           std::uintmax_t fileSize) {
    // The importer reads each count's leading digits and ignores what follows ("1\x01" is 1,
    // "x" is 0), so the check reads them the same way (the fuzzer found "1350000000 1\x01").
    auto vertices = parseLeadingCount(token);
    if (!vertices)
        return "OFF header declares a vertex count too large to be read: " + std::string(token);
    auto faceToken = tokens.next();
    auto faces = faceToken ? parseLeadingCount(*faceToken) : std::uintmax_t(0);
    if (!faces)
        return "OFF header declares a face count too large to be read: " + std::string(*faceToken);
    // Binary coordinates take 4 bytes each, ASCII ones at least 2; faces at least a count.
    return compareWithSize("OFF", tokens.offset(),
                           {{"vertices", *vertices, coordinates * kMinAsciiNumberBytes},
                            {"faces", *faces, kMinAsciiNumberBytes}},
                           fileSize);
}

// A file named *.off without an OFF keyword: the importer reads it all the same, its counts
// from the first number on (the fuzzer found "! # ...OFF\n0675000000 1", 675 million
// vertices in 156 bytes, which the importer tried to allocate).
std::string checkHeaderlessOff(std::string_view head, std::uintmax_t fileSize) {
    OffTokens tokens(head);
    for (int i = 0; i < 64; ++i) {
        auto token = tokens.next();
        if (!token) return {};
        if ((*token)[0] >= '0' && (*token)[0] <= '9') return checkOffCounts(tokens, *token, 3, fileSize);
    }
    return {};
}

// OFF: "[ST][C][N][4][n]OFF", for nOFF the dimension, then "vertices faces edges".
std::string checkOff(std::string_view head, std::uintmax_t fileSize, bool namedOff) {
    OffTokens tokens(head);
    auto keyword = tokens.next();
    // The importer matches the keyword as a prefix: "NOFF1350000000 1 0" is NOFF, then the
    // counts (the fuzzer found it, 16 GB of vertices in 34 bytes).
    const std::size_t at = keyword ? keyword->find("OFF") : std::string_view::npos;
    const bool isKeyword = at != std::string_view::npos &&
                           keyword->substr(0, at).find_first_not_of("STCN4n") == std::string_view::npos;
    if (!isKeyword) return namedOff ? checkHeaderlessOff(head, fileSize) : std::string();
    const std::string_view prefix = keyword->substr(0, at);
    std::uintmax_t coordinates = prefix.find('4') != std::string_view::npos ? 4 : 3;
    std::optional<std::string_view> token;
    if (keyword->size() > at + 3) token = keyword->substr(at + 3);
    else token = tokens.next();
    if (token && prefix.find('n') != std::string_view::npos) {
        auto dimension = parseCount(*token);
        if (!dimension) return {};
        coordinates = std::max<std::uintmax_t>(*dimension, 1);
        token = tokens.next();
    }
    if (!token || *token == "BINARY") return {};  // the importer refuses binary OFF itself
    return checkOffCounts(tokens, *token, coordinates, fileSize);
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
            const bool list = w.size() >= 2 && w[1] == "list";
            const std::uintmax_t bytes = plyScalarBytes(w.size() >= 2 ? w[list ? 2 : 1] : "");
            claims.back().minBytes += ascii ? kMinAsciiNumberBytes : std::max<std::uintmax_t>(bytes, 1);
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
    // OFF headers are three lines at most, bar comments; 64 KiB covers any real one.
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return checkOff(std::string_view(head).substr(0, 1 << 16), fileSize, extension == ".off");
}

}  // namespace rs
