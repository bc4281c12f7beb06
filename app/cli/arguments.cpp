// Strict argument parsing: unknown options, missing values and bad numbers are usage errors.
#include "arguments.h"

#include <charconv>
#include <cmath>

namespace rs::cli {

Arguments::Arguments(int argc, char** argv, int first, const OptionSpec& spec) {
    for (int i = first; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg.size() > 1 && arg[0] == '-') {
            std::string value;
            bool inlineValue = false;
            if (auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
                value = arg.substr(eq + 1);
                arg = arg.substr(0, eq);
                inlineValue = true;
            }
            if (auto alias = spec.aliases.find(arg); alias != spec.aliases.end())
                arg = alias->second;
            if (spec.flags.count(arg)) {
                if (inlineValue) throw UsageError{"option " + arg + " takes no value"};
                flags_.insert(arg);
            } else if (spec.valued.count(arg)) {
                if (!inlineValue) {
                    if (i + 1 >= argc) throw UsageError{"option " + arg + " needs a value"};
                    value = argv[++i];
                }
                values_[arg] = value;
            } else {
                throw UsageError{"unknown option '" + arg + "'"};
            }
        } else {
            positional_.push_back(arg);
        }
    }
}

bool Arguments::has(const std::string& name) const {
    return flags_.count(name) || values_.count(name);
}

std::optional<std::string> Arguments::value(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::optional<int> Arguments::intValue(const std::string& name, int lo, int hi) const {
    auto text = value(name);
    if (!text) return std::nullopt;
    int v = 0;
    const char* end = text->data() + text->size();
    auto [ptr, ec] = std::from_chars(text->data(), end, v);
    if (ec != std::errc() || ptr != end || text->empty())
        throw UsageError{name + " expects a whole number, got '" + *text + "'"};
    if (v < lo || v > hi)
        throw UsageError{name + " must be between " + std::to_string(lo) + " and " +
                         std::to_string(hi) + ", got " + std::to_string(v)};
    return v;
}

std::optional<double> Arguments::numberValue(const std::string& name) const {
    auto text = value(name);
    if (!text) return std::nullopt;
    double v = 0.0;
    const char* end = text->data() + text->size();
    // from_chars, unlike strtod, ignores the C locale and takes no leading spaces or '+'.
    auto [ptr, ec] = std::from_chars(text->data(), end, v);
    if (ec != std::errc() || ptr != end || text->empty() || !std::isfinite(v))
        throw UsageError{name + " expects a number, got '" + *text + "'"};
    return v;
}

}  // namespace rs::cli
