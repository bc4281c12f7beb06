// Refusing mesh files whose header declares more elements than the file can hold.
#pragma once

#include <cstdint>
#include <string>

namespace rs {

/// Checks the element counts an OFF or PLY header (ASCII or binary) declares against
/// `fileSize`: every vertex and face needs some bytes, so a header that claims two billion
/// vertices in a small file is a lie that would make the importer allocate for minutes.
/// Returns "" when the counts fit or the file is in another format, else why it is refused.
std::string checkMeshHeader(const std::string& path, std::uintmax_t fileSize);

}  // namespace rs
