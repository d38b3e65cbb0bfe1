#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raystep {

// Base64 (RFC 4648, section 4: the standard alphabet, padded with '='), for the bytes the grader
// carries as text: a probe's image answers (protocol/image_json.h) and the images inside a report
// (report/data_url.h).

inline constexpr char kBase64Alphabet[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/// The bytes in base64.
inline std::string base64(std::string_view bytes) {
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    // Each 3 bytes become 4 characters of 6 bits; a last group of 1 or 2 bytes is padded.
    for (std::size_t at = 0; at < bytes.size(); at += 3) {
        const std::size_t count = std::min<std::size_t>(3, bytes.size() - at);
        std::uint32_t group = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t byte = k < count ? static_cast<unsigned char>(bytes[at + k]) : 0u;
            group = (group << 8) | byte;
        }
        for (std::size_t k = 0; k < 4; ++k) {
            text += k <= count ? kBase64Alphabet[(group >> (18 - 6 * k)) & 0x3F] : '=';
        }
    }
    return text;
}

/// The bytes that `text` holds in base64. Throws std::invalid_argument when it is not base64 of
/// a whole number of groups: a probe's answer is never trusted.
inline std::string unbase64(const std::string& text) {
    if (text.size() % 4 != 0) throw std::invalid_argument("base64 of a wrong length");
    const auto sextet = [](char c) {
        const char* found = std::strchr(kBase64Alphabet, c);
        if (c == '\0' || !found) throw std::invalid_argument("not base64");
        return static_cast<std::uint32_t>(found - kBase64Alphabet);
    };
    std::string bytes;
    bytes.reserve(text.size() / 4 * 3);
    for (std::size_t k = 0; k < text.size(); k += 4) {
        const int pad = (text[k + 3] == '=') + (text[k + 2] == '=');
        std::uint32_t chunk = 0;
        for (int c = 0; c < 4; ++c) {
            chunk =
                (chunk << 6) | (c >= 4 - pad ? 0u : sextet(text[k + static_cast<std::size_t>(c)]));
        }
        bytes += static_cast<char>((chunk >> 16) & 255);
        if (pad < 2) bytes += static_cast<char>((chunk >> 8) & 255);
        if (pad < 1) bytes += static_cast<char>(chunk & 255);
    }
    return bytes;
}

}  // namespace raystep
