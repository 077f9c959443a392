//! Operator impls shared by [`super::Interval`] and [`crate::num::MpfrInterval`]:
//! `+ − × ÷` for owned and borrowed operands, with an `f64` on either side (lifted
//! exactly into the interval type, see `lift_f64`), compound assignment, and negation.
//! Each forwards to the type's inherent `add/sub/mul/div(&self, &Self)`.

/// `impl_interval_ops!(Type, |template, v| lift)`: `lift` turns the f64 `v` into a
/// `Type` in the precision of `template`.
macro_rules! impl_interval_ops {
    ($T:ty, $lift:expr) => {
        impl_interval_ops!(@op $T, $lift, Add, add, AddAssign, add_assign);
        impl_interval_ops!(@op $T, $lift, Sub, sub, SubAssign, sub_assign);
        impl_interval_ops!(@op $T, $lift, Mul, mul, MulAssign, mul_assign);
        impl_interval_ops!(@op $T, $lift, Div, div, DivAssign, div_assign);

        impl std::ops::Neg for $T {
            type Output = $T;
            #[inline]
            fn neg(self) -> $T {
                <$T>::neg(&self)
            }
        }
        impl std::ops::Neg for &$T {
            type Output = $T;
            #[inline]
            fn neg(self) -> $T {
                <$T>::neg(self)
            }
        }
    };
    (@op $T:ty, $lift:expr, $Tr:ident, $m:ident, $TrA:ident, $ma:ident) => {
        impl std::ops::$Tr<$T> for $T {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: $T) -> $T {
                <$T>::$m(&self, &rhs)
            }
        }
        impl std::ops::$Tr<&$T> for $T {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: &$T) -> $T {
                <$T>::$m(&self, rhs)
            }
        }
        impl std::ops::$Tr<$T> for &$T {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: $T) -> $T {
                <$T>::$m(self, &rhs)
            }
        }
        impl std::ops::$Tr<&$T> for &$T {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: &$T) -> $T {
                <$T>::$m(self, rhs)
            }
        }
        impl std::ops::$Tr<f64> for $T {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: f64) -> $T {
                let r = ($lift)(&self, rhs);
                <$T>::$m(&self, &r)
            }
        }
        impl std::ops::$Tr<f64> for &$T {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: f64) -> $T {
                let r = ($lift)(self, rhs);
                <$T>::$m(self, &r)
            }
        }
        impl std::ops::$Tr<$T> for f64 {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: $T) -> $T {
                let l = ($lift)(&rhs, self);
                <$T>::$m(&l, &rhs)
            }
        }
        impl std::ops::$Tr<&$T> for f64 {
            type Output = $T;
            #[inline]
            fn $m(self, rhs: &$T) -> $T {
                let l = ($lift)(rhs, self);
                <$T>::$m(&l, rhs)
            }
        }
        impl std::ops::$TrA<$T> for $T {
            #[inline]
            fn $ma(&mut self, rhs: $T) {
                *self = <$T>::$m(self, &rhs);
            }
        }
        impl std::ops::$TrA<&$T> for $T {
            #[inline]
            fn $ma(&mut self, rhs: &$T) {
                *self = <$T>::$m(self, rhs);
            }
        }
        impl std::ops::$TrA<f64> for $T {
            #[inline]
            fn $ma(&mut self, rhs: f64) {
                let r = ($lift)(self, rhs);
                *self = <$T>::$m(self, &r);
            }
        }
    };
}

pub(crate) use impl_interval_ops;

/// Inside a trait impl for `$T`: trait methods that forward to the inherent methods of
/// the same name (`fn m(&self) -> Self`, `fn m(&self, other: &Self) -> R`, …), so that
/// `Real`/`IntervalLike` impls list only what differs between the interval types.
macro_rules! forward_to_inherent {
    ($T:ty; unary: $($u:ident),* ; binary: $($b:ident -> $R:ty),* ; predicates: $($p:ident),*) => {
        $(
            #[inline]
            fn $u(&self) -> Self {
                <$T>::$u(self)
            }
        )*
        $(
            #[inline]
            fn $b(&self, other: &Self) -> $R {
                <$T>::$b(self, other)
            }
        )*
        $(
            #[inline]
            fn $p(&self) -> bool {
                <$T>::$p(self)
            }
        )*
    };
}

pub(crate) use forward_to_inherent;

impl_interval_ops!(super::Interval, |_: &super::Interval, v: f64| {
    super::Interval::point(v)
});
