#include "app/submit/stored_zip.h"

#include <array>
#include <limits>
#include <set>
#include <stdexcept>

namespace raystep {

namespace {

// Record signatures and fields of APPNOTE.TXT, section 4.3.
constexpr std::uint32_t kLocalHeader = 0x04034b50;
constexpr std::uint32_t kCentralHeader = 0x02014b50;
constexpr std::uint32_t kEndOfCentralDirectory = 0x06054b50;
// Version 2.0, the version every reader takes: stored entries need 1.0, but 2.0 is what most
// writers put and no reader refuses it. "Made by" host 0 (MS-DOS attributes, none set), so that
// an unpacker gives the files its user's default permissions.
constexpr std::uint16_t kVersion = 20;
constexpr std::uint16_t kStored = 0;
// MS-DOS date of 1980-01-01 (year 0 from 1980, month 1, day 1), time 00:00:00: the earliest a
// zip can say. C++17 has no portable conversion from a file's time to a calendar date, and a
// fixed date makes the archive depend on the files' contents alone.
constexpr std::uint16_t kDosDate = (1 << 5) | 1;
constexpr std::uint16_t kDosTime = 0;

void put16(std::string& out, std::uint16_t value) {
    out.push_back(static_cast<char>(value & 0xff));
    out.push_back(static_cast<char>(value >> 8));
}

void put32(std::string& out, std::uint32_t value) {
    put16(out, static_cast<std::uint16_t>(value & 0xffff));
    put16(out, static_cast<std::uint16_t>(value >> 16));
}

std::uint32_t checked32(std::size_t value, const char* what) {
    if (value > std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument(std::string("zip: ") + what + " past 4 GiB needs ZIP64");
    return static_cast<std::uint32_t>(value);
}

void check_name(const std::string& name, std::set<std::string>& seen) {
    if (name.empty() || name.front() == '/' || name.size() > 0xffff)
        throw std::invalid_argument("zip: entry name '" + name +
                                    "' is empty, absolute or too long");
    if (!seen.insert(name).second)
        throw std::invalid_argument("zip: entry name '" + name + "' given twice");
}

// The fields a local header and a central directory header share, from "version needed" to the
// name's length (APPNOTE 4.3.7 and 4.3.12).
void put_common_fields(std::string& out, const ZipEntry& entry, std::uint32_t crc) {
    put16(out, kVersion);
    put16(out, 0);  // general purpose flags: no encryption, sizes in the header
    put16(out, kStored);
    put16(out, kDosTime);
    put16(out, kDosDate);
    put32(out, crc);
    const std::uint32_t size = checked32(entry.contents.size(), "an entry");
    put32(out, size);  // compressed size: stored, so the same
    put32(out, size);
    put16(out, static_cast<std::uint16_t>(entry.name.size()));
    put16(out, 0);  // extra field length
}

}  // namespace

std::uint32_t crc32(std::string_view bytes) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int bit = 0; bit < 8; ++bit)
                c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    std::uint32_t crc = 0xffffffffu;
    for (const char byte : bytes)
        crc = table[(crc ^ static_cast<unsigned char>(byte)) & 0xff] ^ (crc >> 8);
    return crc ^ 0xffffffffu;
}

std::string stored_zip(const std::vector<ZipEntry>& entries) {
    if (entries.size() > 0xffff)
        throw std::invalid_argument("zip: over 65,535 entries needs ZIP64");
    std::set<std::string> seen;
    std::string out;
    std::string directory;
    for (const ZipEntry& entry : entries) {
        check_name(entry.name, seen);
        const std::uint32_t crc = crc32(entry.contents);
        const std::uint32_t offset = checked32(out.size(), "the archive");

        // Local header, then the bytes as they are
        put32(out, kLocalHeader);
        put_common_fields(out, entry, crc);
        out += entry.name;
        out += entry.contents;

        // Its central directory header, which readers trust over the local one
        put32(directory, kCentralHeader);
        put16(directory, kVersion);  // made by
        put_common_fields(directory, entry, crc);
        put16(directory, 0);  // comment length
        put16(directory, 0);  // disk number
        put16(directory, 0);  // internal attributes
        put32(directory, 0);  // external attributes
        put32(directory, offset);
        directory += entry.name;
    }

    // End of central directory: one disk, every entry on it
    const std::uint32_t directory_offset = checked32(out.size(), "the archive");
    const std::uint32_t directory_size = checked32(directory.size(), "the central directory");
    out += directory;
    checked32(out.size(), "the archive");
    put32(out, kEndOfCentralDirectory);
    put16(out, 0);  // this disk
    put16(out, 0);  // the disk where the directory starts
    put16(out, static_cast<std::uint16_t>(entries.size()));
    put16(out, static_cast<std::uint16_t>(entries.size()));
    put32(out, directory_size);
    put32(out, directory_offset);
    put16(out, 0);  // comment length
    return out;
}

}  // namespace raystep
