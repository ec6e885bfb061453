#pragma once
// The run's one hash for names and seeds: 64-bit FNV-1a over bytes, and splitmix64's finaliser to
// spread a sum of seeds over all 64 bits. Both are fixed arithmetic, so every platform derives
// the same seeds and the same graph hash.
#include <cstdint>
#include <string_view>

namespace kestrel::detail {

/// FNV-1a's 64-bit offset basis and prime.
inline constexpr std::uint64_t kFnv1aOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kFnv1aPrime = 1099511628211ull;

/// 64-bit FNV-1a of `bytes`, starting from `basis`.
constexpr std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t basis = kFnv1aOffsetBasis) {
  std::uint64_t h = basis;
  for (unsigned char c : bytes) h = (h ^ c) * kFnv1aPrime;
  return h;
}

/// splitmix64's finaliser: the golden-ratio increment is the caller's, this mixes.
constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// splitmix64's increment, 2^64 / the golden ratio.
inline constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ull;

/// A node's seed: splitmix64_mix(run_seed + fnv1a64(node_id, kNodeSeedBasis) + kGoldenGamma).
/// kNodeSeedBasis is FNV-1a's offset basis without its last digit (1469598103934665603, not
/// 14695981039346656037). Every recorded run was seeded with it, so it stays: changing it would
/// change every result of every seed.
inline constexpr std::uint64_t kNodeSeedBasis = 1469598103934665603ull;
constexpr std::uint64_t node_seed(std::uint64_t run_seed, std::string_view node_id) {
  return splitmix64_mix(run_seed + fnv1a64(node_id, kNodeSeedBasis) + kGoldenGamma);
}

/// A component's seed, from its owner's seed and the parameter that names it:
/// splitmix64_mix(owner_seed + kGoldenGamma * (fnv1a64(name) | 1)), with FNV-1a's own basis.
constexpr std::uint64_t component_seed(std::uint64_t owner_seed, std::string_view name) {
  return splitmix64_mix(owner_seed + kGoldenGamma * (fnv1a64(name) | 1u));
}

}  // namespace kestrel::detail
