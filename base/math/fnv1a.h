#pragma once

#include <cstdint>
#include <string_view>

namespace raystep {

// 64-bit FNV-1a (Fowler, Noll and Vo): a digest that is the same on every platform, for telling
// inputs apart, not for defending against a forged one. Every bit of a value folded in changes
// the result; bytes fold as values below 256, and 64-bit words fold whole.

/// The digest of nothing: FNV-1a's 64-bit offset basis.
inline constexpr std::uint64_t kFnv1aBasis = 0xcbf29ce484222325u;

/// Folds one value into a digest: exclusive or, then FNV-1a's 64-bit prime.
inline constexpr std::uint64_t fnv1a_fold(std::uint64_t digest, std::uint64_t value) {
    return (digest ^ value) * 0x100000001b3u;
}

/// The digest of `bytes`, folded one byte at a time onto `digest`.
inline constexpr std::uint64_t fnv1a(std::string_view bytes, std::uint64_t digest = kFnv1aBasis) {
    for (const char c : bytes)
        digest = fnv1a_fold(digest, static_cast<unsigned char>(c));
    return digest;
}

}  // namespace raystep
