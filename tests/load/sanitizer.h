// Whether these tests run under AddressSanitizer (scripts/test-hardening.sh). Bounds on time and
// memory hold for the build users run: the instrumented daemon carries shadow memory, redzones
// and a quarantine of freed blocks and runs several times slower, so the sanitized run prints
// those figures without holding them to the bounds, and still asserts every other outcome.
#pragma once

namespace geodesic::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace geodesic::test
