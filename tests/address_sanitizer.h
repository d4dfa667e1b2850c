#pragma once
// Whether this test binary runs under AddressSanitizer. ASan reserves
// terabytes of shadow address space at start-up (so a process under an
// address-space limit cannot even begin) and aborts on allocations beyond
// its own maximum instead of returning null: tests of both skip under it.

namespace tetblend::test {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

}  // namespace tetblend::test
