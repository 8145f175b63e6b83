//! Stein's binary gcd on machine words, for the small paths of `Integer` and `Rational`, and
//! the gcd of big integers that takes a short side to a word first.

use num_bigint::{BigInt, BigUint};
use num_traits::ToPrimitive;

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

/// `gcd(|a|, |b|)` of big integers. When a side fits a `u128`, one remainder brings the other
/// to a word: `num-integer`'s binary gcd shifts the long side one step per bit, so that the
/// `gcd(10^99900, 1)` that normalising a big integer takes cost a second, and `(10^999)^999`
/// a minute and a half.
pub(crate) fn gcd_bigint(a: &BigInt, b: &BigInt) -> BigInt {
    let (x, y) = (a.magnitude(), b.magnitude());
    let with_short = |long: &BigUint, short: u128| -> BigInt {
        if short == 0 {
            return BigInt::from(long.clone());
        }
        let r = (long % short).to_u128().expect("a remainder below a u128");
        BigInt::from(gcd_u128(short, r))
    };
    match (x.to_u128(), y.to_u128()) {
        (Some(p), Some(q)) => BigInt::from(gcd_u128(p, q)),
        (Some(p), None) => with_short(y, p),
        (None, Some(q)) => with_short(x, q),
        (None, None) => BigInt::from(lehmer_gcd(x.clone(), y.clone())),
    }
}

/// `gcd(a, b)` by Lehmer's algorithm (Knuth, TAOCP vol. 2, 4.5.2, Algorithm L): the quotients
/// of Euclid's algorithm are found from the leading 63 bits of `a` and `b` while they agree
/// with what the whole numbers would give, and applied to them at once as one linear
/// combination; a division takes over when the leading bits decide nothing. The long sides
/// then cost a pass per word of quotients, not one per bit as in the binary gcd of
/// `num-integer` (a gcd of two numbers of three million bits: minutes).
pub(crate) fn lehmer_gcd(mut a: BigUint, mut b: BigUint) -> BigUint {
    if a < b {
        std::mem::swap(&mut a, &mut b);
    }
    loop {
        if let Some(short) = b.to_u128() {
            if short == 0 {
                return a;
            }
            let r = (&a % short).to_u128().expect("a remainder below a u128");
            return BigUint::from(gcd_u128(short, r));
        }
        let shift = a.bits() - 63;
        let mut x = i128::from((&a >> shift).to_u64().expect("63 bits"));
        let mut y = i128::from((&b >> shift).to_u64().expect("63 bits"));
        // The cofactors: a' = A a + B b, b' = C a + D b, each bounded by 2^63 in magnitude.
        let (mut ca, mut cb, mut cc, mut cd) = (1i128, 0i128, 0i128, 1i128);
        while y + cc != 0 && y + cd != 0 {
            let q = (x + ca) / (y + cc);
            if q != (x + cb) / (y + cd) {
                break;
            }
            (ca, cc) = (cc, ca - q * cc);
            (cb, cd) = (cd, cb - q * cd);
            (x, y) = (y, x - q * y);
        }
        if cb == 0 {
            let r = &a % &b;
            a = b;
            b = r;
        } else {
            let (ia, ib) = (BigInt::from(a), BigInt::from(b));
            let combine = |p: i128, q: i128| -> BigUint {
                (&ia * p + &ib * q)
                    .to_biguint()
                    .expect("Lehmer's cofactors keep the remainders nonnegative")
            };
            a = combine(ca, cb);
            b = combine(cc, cd);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer as _;
    use proptest::prelude::*;

    /// A big integer from words, times a common factor from words, so that the gcds are
    /// often long.
    fn big(words: &[u64], factor: &[u64]) -> BigUint {
        let from = |w: &[u64]| {
            w.iter().fold(BigUint::from(0u8), |acc, &x| {
                (acc << 64u32) + BigUint::from(x)
            })
        };
        from(words) * from(factor).max(BigUint::from(1u8))
    }

    proptest! {
        #[test]
        fn lehmer_gcd_is_the_gcd(
            a in prop::collection::vec(any::<u64>(), 0..12),
            b in prop::collection::vec(any::<u64>(), 0..12),
            f in prop::collection::vec(any::<u64>(), 0..4),
        ) {
            let (a, b) = (big(&a, &f), big(&b, &f));
            prop_assert_eq!(lehmer_gcd(a.clone(), b.clone()), a.gcd(&b));
        }
    }

    #[test]
    fn lehmer_gcd_of_fibonacci_neighbours_and_powers() {
        // Consecutive Fibonacci numbers take Euclid's longest path: every quotient is 1.
        let (mut f, mut g) = (BigUint::from(0u8), BigUint::from(1u8));
        for _ in 0..2000 {
            (f, g) = (g.clone(), f + g);
        }
        assert_eq!(lehmer_gcd(f.clone(), g.clone()), BigUint::from(1u8));
        let ten = BigUint::from(10u8).pow(5000);
        let six = BigUint::from(6u8).pow(4000);
        assert_eq!(lehmer_gcd(ten, six), BigUint::from(2u8).pow(4000));
    }

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
