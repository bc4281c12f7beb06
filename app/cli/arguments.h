// Command-line parsing for raystudio-cli: options with values, flags, and checked numbers.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rs::cli {

/// Thrown for bad usage; main() prints it and exits with 2.
struct UsageError {
    std::string message;
};

/// The options one command accepts: names (with "--") that take a value, and plain flags.
struct OptionSpec {
    std::set<std::string> valued;
    std::set<std::string> flags;
    std::map<std::string, std::string> aliases;  ///< e.g. "-o" -> "--output".
};

/// Parsed arguments of one command.
class Arguments {
public:
    /// Parses argv[first..]; throws UsageError naming the offending argument.
    Arguments(int argc, char** argv, int first, const OptionSpec& spec);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& name) const;
    std::optional<std::string> value(const std::string& name) const;
    /// The integer value of `name` in [lo, hi], or nullopt when absent; throws UsageError
    /// when it is not a whole number or out of range.
    std::optional<int> intValue(const std::string& name, int lo, int hi) const;
    /// The finite number `name` gives, or nullopt when absent; throws UsageError when it is
    /// not a number (ranges differ per option, so callers check them).
    std::optional<double> numberValue(const std::string& name) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::set<std::string> flags_;
};

}  // namespace rs::cli
