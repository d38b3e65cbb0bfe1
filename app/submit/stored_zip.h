#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// One file of a zip archive: its path inside the archive ('/' between folders) and its bytes.
struct ZipEntry {
    std::string name;
    std::string contents;
};

/// The CRC-32 of `bytes` that zip (and gzip, PNG) stores: ISO-HDLC, reflected polynomial
/// 0xEDB88320, starting from and finished with all ones. "123456789" gives 0xCBF43926.
std::uint32_t crc32(std::string_view bytes);

/// The bytes of a zip archive holding `entries` in order, each stored (not compressed) with its
/// CRC-32, as PKWARE's APPNOTE.TXT (section 4.3) lays it out: a local header and the data for
/// each entry, then the central directory and its end record. Every entry is dated 1980-01-01
/// 00:00, so that the same files always give the same bytes. Throws std::invalid_argument for an
/// empty, absolute or over-long name, a name given twice, or sizes past what a zip without ZIP64
/// records hold (4 GiB in all, 65,535 entries).
std::string stored_zip(const std::vector<ZipEntry>& entries);

}  // namespace raystep
