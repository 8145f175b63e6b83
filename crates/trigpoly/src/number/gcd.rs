//! Stein's binary gcd on machine words, for the small paths of `Integer` and `Rational`.

/// Defines `fn $name(a: $t, b: $t) -> $t`, the binary gcd (`gcd(0, 0) = 0`).
macro_rules! binary_gcd_for {
    ($name:ident, $t:ty) => {
        pub(crate) fn $name(mut a: $t, mut b: $t) -> $t {
            if a == 0 {
                return b;
            }
            if b == 0 {
                return a;
            }
            let shift = (a | b).trailing_zeros();
            // A power of two (a content of 1 or 2 met again and again while a polynomial is
            // normalised) shares only its twos.
            if a.is_power_of_two() || b.is_power_of_two() {
                return 1 << shift;
            }
            a >>= a.trailing_zeros();
            loop {
                b >>= b.trailing_zeros();
                if a > b {
                    std::mem::swap(&mut a, &mut b);
                }
                b -= a;
                if b == 0 {
                    return a << shift;
                }
            }
        }
    };
}

binary_gcd_for!(binary_gcd, u64);
binary_gcd_for!(gcd_u128, u128);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binary_gcd_matches_euclid() {
        fn euclid(a: u128, b: u128) -> u128 {
            if b == 0 {
                a
            } else {
                euclid(b, a % b)
            }
        }
        for a in 0..60u64 {
            for b in 0..60u64 {
                assert_eq!(binary_gcd(a, b) as u128, euclid(a as u128, b as u128));
                assert_eq!(
                    gcd_u128((a as u128 * 3) << 70, (b as u128 * 3) << 70),
                    euclid((a as u128 * 3) << 70, (b as u128 * 3) << 70)
                );
            }
        }
        assert_eq!(binary_gcd(u64::MAX, u64::MAX), u64::MAX);
    }
}
