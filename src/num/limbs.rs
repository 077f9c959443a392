//! Unsigned multi-limb integer primitives on slices of 64-bit limbs (little endian,
//! "normalised" = no zero top limb, the empty slice being 0), for the fixed-width dyadic
//! numbers of [`super::dyadic`]. Every function is exact; a result that does not fit the
//! output buffer is reported (`None`), never truncated. No allocation.

use std::cmp::Ordering;

/// The length of `a[..len]` without its zero top limbs.
#[inline(always)]
pub(crate) fn trim(a: &[u64], mut len: usize) -> usize {
    while len > 0 && a[len - 1] == 0 {
        len -= 1;
    }
    len
}

/// The bit length of a normalised magnitude (0 for 0).
#[inline(always)]
pub(crate) fn bit_len(a: &[u64]) -> u64 {
    match a.last() {
        None => 0,
        Some(t) => 64 * (a.len() as u64 - 1) + u64::from(64 - t.leading_zeros()),
    }
}

/// `out = a · 2^s`; the normalised length, or `None` when it does not fit `out`.
#[inline(always)]
pub(crate) fn shl_into(a: &[u64], s: u64, out: &mut [u64]) -> Option<usize> {
    let n = a.len();
    if n == 0 {
        return Some(0);
    }
    if s / 64 >= out.len() as u64 {
        return None;
    }
    let (w, b) = ((s / 64) as usize, (s % 64) as u32);
    if b == 0 {
        if n + w > out.len() {
            return None;
        }
        out[..w].fill(0);
        out[w..w + n].copy_from_slice(a);
        return Some(n + w);
    }
    let top = a[n - 1] >> (64 - b);
    let len = n + w + usize::from(top != 0);
    if len > out.len() {
        return None;
    }
    out[..w].fill(0);
    let mut carry = 0u64;
    for i in 0..n {
        out[w + i] = (a[i] << b) | carry;
        carry = a[i] >> (64 - b);
    }
    if top != 0 {
        out[w + n] = top;
    }
    Some(len)
}

/// Compare two normalised magnitudes.
#[inline(always)]
pub(crate) fn cmp(a: &[u64], b: &[u64]) -> Ordering {
    if a.len() != b.len() {
        return a.len().cmp(&b.len());
    }
    for i in (0..a.len()).rev() {
        if a[i] != b[i] {
            return a[i].cmp(&b[i]);
        }
    }
    Ordering::Equal
}

/// `x[..xl] += b` in place; the normalised length, or `None` when the carry does not fit.
#[inline(always)]
pub(crate) fn add_in_place(x: &mut [u64], xl: usize, b: &[u64]) -> Option<usize> {
    let n = xl.max(b.len());
    if n > x.len() {
        return None;
    }
    x[xl..n].fill(0);
    let mut carry = 0u64;
    for i in 0..n {
        let bi = if i < b.len() { b[i] } else { 0 };
        let (s1, c1) = x[i].overflowing_add(bi);
        let (s2, c2) = s1.overflowing_add(carry);
        x[i] = s2;
        carry = u64::from(c1 | c2);
    }
    if carry == 0 {
        Some(n)
    } else if n < x.len() {
        x[n] = 1;
        Some(n + 1)
    } else {
        None
    }
}

/// `x[..xl] = |x − b|` in place (both normalised); the normalised length and whether
/// `b > x` (the difference changed sign). `None` when `b` does not fit `x`.
#[inline(always)]
pub(crate) fn sub_in_place(x: &mut [u64], xl: usize, b: &[u64]) -> Option<(usize, bool)> {
    let n = xl.max(b.len());
    if n > x.len() {
        return None;
    }
    x[xl..n].fill(0);
    let flip = cmp(&x[..xl], b) == Ordering::Less;
    let mut borrow = 0u64;
    for i in 0..n {
        let bi = if i < b.len() { b[i] } else { 0 };
        let (hi, lo) = if flip { (bi, x[i]) } else { (x[i], bi) };
        let (d1, c1) = hi.overflowing_sub(lo);
        let (d2, c2) = d1.overflowing_sub(borrow);
        x[i] = d2;
        borrow = u64::from(c1 | c2);
    }
    Some((trim(x, n), flip))
}

/// `out = a · b` (both normalised, non-zero); the normalised length, or `None` when the
/// product needs more limbs than `out` has.
#[inline(always)]
pub(crate) fn mul_into(a: &[u64], b: &[u64], out: &mut [u64]) -> Option<usize> {
    let (la, lb) = (a.len(), b.len());
    if bit_len(a) + bit_len(b) > 64 * out.len() as u64 {
        return None;
    }
    // The product is below 2^(bits a + bits b) ≤ 2^(64·out.len()): every limb written
    // below fits, and a carry into position `out.len()` is zero.
    let m = (la + lb).min(out.len());
    out[..m].fill(0);
    for i in 0..la {
        let mut carry = 0u128;
        let ai = u128::from(a[i]);
        for j in 0..lb {
            let t = ai * u128::from(b[j]) + u128::from(out[i + j]) + carry;
            out[i + j] = t as u64;
            carry = t >> 64;
        }
        if i + lb < out.len() {
            out[i + lb] = carry as u64;
        }
    }
    Some(trim(out, m))
}

/// `x[..len] >>= s` in place for `s` below the bit length; the new normalised length.
#[inline(always)]
pub(crate) fn shr_in_place(x: &mut [u64], len: usize, s: u64) -> usize {
    let (w, b) = ((s / 64) as usize, (s % 64) as u32);
    if b == 0 {
        x.copy_within(w..len, 0);
    } else {
        for i in w..len {
            let hi = if i + 1 < len { x[i + 1] << (64 - b) } else { 0 };
            x[i - w] = (x[i] >> b) | hi;
        }
    }
    trim(x, len - w)
}

/// The number of trailing zero bits of a non-zero magnitude.
#[inline(always)]
pub(crate) fn trailing_zeros(a: &[u64]) -> u64 {
    let mut w = 0;
    while a[w] == 0 {
        w += 1;
    }
    64 * w as u64 + u64::from(a[w].trailing_zeros())
}

/// `(a·2^ea) + (−1)^neg_b (b·2^eb)` for magnitudes `a`, `b` of sign `+`, written into
/// `out` at the smaller exponent: `(negative, exponent, length)`; `None` when the
/// aligned operand does not fit `out`. Exact.
#[inline(always)]
pub(crate) fn signed_sum(
    a: &[u64],
    ea: i64,
    neg_b: bool,
    b: &[u64],
    eb: i64,
    out: &mut [u64],
) -> Option<(bool, i64, usize)> {
    // Shift the operand with the larger exponent; then add or subtract the other.
    let (x, xneg, y, yneg, e, d) = if ea >= eb {
        (a, false, b, neg_b, eb, (ea - eb) as u64)
    } else {
        (b, neg_b, a, false, ea, (eb - ea) as u64)
    };
    let xl = shl_into(x, d, out)?;
    if xneg == yneg {
        Some((xneg, e, add_in_place(out, xl, y)?))
    } else {
        let (len, flip) = sub_in_place(out, xl, y)?;
        Some((xneg != flip, e, len))
    }
}

/// Compare `a·2^ea` with `b·2^eb` (normalised, non-negative). `None` only when the
/// alignment needs more than `scratch` holds.
pub(crate) fn cmp_scaled(
    a: &[u64],
    ea: i64,
    b: &[u64],
    eb: i64,
    scratch: &mut [u64],
) -> Option<Ordering> {
    match (a.is_empty(), b.is_empty()) {
        (true, true) => return Some(Ordering::Equal),
        (true, false) => return Some(Ordering::Less),
        (false, true) => return Some(Ordering::Greater),
        _ => {}
    }
    // The top bit positions decide unless they coincide.
    let ta = bit_len(a) as i64 + ea;
    let tb = bit_len(b) as i64 + eb;
    if ta != tb {
        return Some(ta.cmp(&tb));
    }
    Some(if ea >= eb {
        let l = shl_into(a, (ea - eb) as u64, scratch)?;
        cmp(&scratch[..l], b)
    } else {
        let l = shl_into(b, (eb - ea) as u64, scratch)?;
        cmp(a, &scratch[..l])
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Integer;

    fn int(a: &[u64]) -> Integer {
        let mut x = Integer::new();
        for &l in a.iter().rev() {
            x <<= 64;
            x += l;
        }
        x
    }

    fn limbs(seed: &mut u64, n: usize) -> Vec<u64> {
        let mut v: Vec<u64> = (0..n)
            .map(|_| {
                *seed ^= *seed << 13;
                *seed ^= *seed >> 7;
                *seed ^= *seed << 17;
                *seed
            })
            .collect();
        let l = trim(&v, v.len());
        v.truncate(l);
        v
    }

    #[test]
    fn primitives_agree_with_gmp() {
        let mut seed = 0x1234_5678_9ABC_DEF1u64;
        for round in 0..400 {
            let a = limbs(&mut seed, 1 + round % 4);
            let b = limbs(&mut seed, 1 + (round / 4) % 4);
            let mut out = [0u64; 12];
            let l = mul_into(&a, &b, &mut out).unwrap();
            assert_eq!(int(&out[..l]), int(&a) * int(&b));
            let s = (round as u64 * 37) % 200;
            let l = shl_into(&a, s, &mut out).unwrap();
            assert_eq!(int(&out[..l]), int(&a) << s as u32);
            let l2 = shr_in_place(&mut out, l, s);
            assert_eq!(&out[..l2], &a[..]);
            let mut x = [0u64; 12];
            x[..a.len()].copy_from_slice(&a);
            let l = add_in_place(&mut x, a.len(), &b).unwrap();
            assert_eq!(int(&x[..l]), int(&a) + int(&b));
            x[..a.len()].copy_from_slice(&a);
            let (l, flip) = sub_in_place(&mut x, a.len(), &b).unwrap();
            assert_eq!(int(&x[..l]), (int(&a) - int(&b)).abs());
            assert_eq!(flip, int(&a) < int(&b));
            let (ea, eb) = ((round % 7) as i64 - 3, (round % 5) as i64);
            let (neg, e, l) = signed_sum(&a, ea, true, &b, eb, &mut out).unwrap();
            let e0 = ea.min(eb);
            let truth = (int(&a) << (ea - e0) as u32) - (int(&b) << (eb - e0) as u32);
            assert_eq!(e, e0);
            assert_eq!(if neg { -int(&out[..l]) } else { int(&out[..l]) }, truth);
            let mut scratch = [0u64; 12];
            let c = cmp_scaled(&a, ea, &b, eb, &mut scratch).unwrap();
            assert_eq!(
                c,
                (int(&a) << (ea - e0) as u32).cmp(&(int(&b) << (eb - e0) as u32))
            );
        }
        // Results that do not fit are reported, not truncated.
        let mut small = [0u64; 2];
        assert_eq!(mul_into(&[u64::MAX, 1], &[u64::MAX], &mut small), None);
        assert_eq!(shl_into(&[1], 128, &mut small), None);
        let mut x = [u64::MAX, u64::MAX];
        assert_eq!(add_in_place(&mut x, 2, &[1]), None);
    }
}
