// bfloat16: a float's upper 16 bits (sign, the 8-bit exponent, 7 of the 23 mantissa bits), two to a
// uint. Packing rounds to nearest even (≤ 0.2 % off: 8 significant bits); unpacking is a shift or
// a mask, where halves (packHalf2x16, 11 significant bits) are converted in software on llvmpipe,
// which made the cached mode's gather and the indirect resolve slower (docs/PERFORMANCE.md,
// "llvmpipe").
// For finite values (the rounding would carry a NaN's mantissa into the exponent).
uint bfloatBits(float x) {
    uint bits = floatBitsToUint(x);
    return (bits + 0x7fffu + ((bits >> 16) & 1u)) >> 16;
}
uint packBfloat2(vec2 v) { return bfloatBits(v.x) | (bfloatBits(v.y) << 16); }
float unpackBfloatLow(uint word) { return uintBitsToFloat(word << 16); }
float unpackBfloatHigh(uint word) { return uintBitsToFloat(word & 0xffff0000u); }
vec2 unpackBfloat2(uint word) { return vec2(unpackBfloatLow(word), unpackBfloatHigh(word)); }
