#pragma once

#include <filesystem>
#include <string>

namespace caustica {

// What is wrong with an OpenVDB file's header, read before OpenVDB reads
// it, or empty: OpenVDB allocates each length-prefixed string and metadata
// value before reading it, so a file cut short or corrupted can make it
// ask for gigabytes. For file versions 222 to 224 (OpenVDB 3 to 11) every
// length in the header must fit in the file's remaining bytes and every
// grid must end within the file; other versions are left to OpenVDB.
std::string vdb_header_problem(const std::filesystem::path& file);

}  // namespace caustica
