// Numbers on command lines and in text commands are plain decimals, one rule for every
// tool: an optional sign, digits, and (where a fraction is allowed) a point and digits.
// strtol/strtod alone would also take leading blanks, and strtod hex ("0x123"),
// exponents ("1e3"), inf and nan.
#pragma once

namespace cuetrack::platform {

// True when s starts with a plain decimal that ends at '\0' or at `stop` (e.g. ',').
inline bool plainDecimal(const char* s, bool fraction, char stop = '\0') {
  if (*s == '+' || *s == '-') ++s;
  int digits = 0;
  for (; *s >= '0' && *s <= '9'; ++s) ++digits;
  if (fraction && *s == '.')
    for (++s; *s >= '0' && *s <= '9'; ++s) ++digits;
  return digits > 0 && (*s == '\0' || *s == stop);
}

}  // namespace cuetrack::platform
