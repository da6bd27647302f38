#pragma once
// The checksum of rockfrac's binary files: 64-bit FNV-1a (Fowler–Noll–Vo), in two
// layouts over the same offset basis and prime (docs/file-formats.md):
//   fnv1a       byte by byte, the textbook form: state files (io/stateFile.hpp);
//   fnv1aWords  by 8-byte little-endian words (the last one zero-padded), then the
//               length: the Voronoi mesh files (voronoi/voronoiMeshIO.hpp), whose
//               large payloads it hashes with an eighth of the multiplications.
// Both values are stored in files, so neither may change.
#include <cstddef>
#include <cstdint>

namespace rockfrac {

inline constexpr std::uint64_t fnv1aOffsetBasis = 0xcbf29ce484222325ULL;
inline constexpr std::uint64_t fnv1aPrime = 0x100000001b3ULL;

// Byte-wise FNV-1a of `size` bytes, continuing from `hash`.
std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = fnv1aOffsetBasis);

// Word-wise FNV-1a: each 8-byte little-endian word is xor-ed in and multiplied by the
// prime, the last one zero-padded, then the length likewise. Catches truncation, bit
// flips and files from different runs.
std::uint64_t fnv1aWords(const void* data, std::size_t size);

}  // namespace rockfrac
