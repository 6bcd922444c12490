"""Observation and action spaces with the attributes and methods of Gymnasium's ``Box``.

Gymnasium is not a Debian package, so simhuman does not import it; code written against
``gymnasium.spaces.Box`` (shape, dtype, low, high, sample(), seed(), contains()) works on these.
"""

import numpy as np


class Box:
    """A box in R^n: every entry between ``low`` and ``high`` (which may be infinite).

    Args:
        low, high: scalars or arrays broadcast to ``shape``.
        shape: the shape of an element (taken from ``low`` when not given).
        dtype: numpy dtype of elements (float32 by default).
        seed: seed of the random generator ``sample()`` draws from.
    """

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        self.dtype = np.dtype(dtype)
        if shape is None:
            shape = np.shape(low)
        self.shape = tuple(int(n) for n in shape)
        self.low = np.full(self.shape, low, dtype=self.dtype)
        self.high = np.full(self.shape, high, dtype=self.dtype)
        if np.any(self.low > self.high):
            raise ValueError(f"Box: low must be <= high everywhere, got low={low}, high={high}")
        self._np_random = None
        if seed is not None:
            self.seed(seed)

    @property
    def np_random(self):
        """The numpy Generator ``sample()`` uses (seeded on first use when never seeded)."""
        if self._np_random is None:
            self.seed()
        return self._np_random

    def seed(self, seed=None):
        """Seeds the sampler; returns ``[seed]`` as Gymnasium does."""
        self._np_random = np.random.default_rng(seed)
        return [seed]

    def is_bounded(self, manner="both"):
        """Whether every entry is bounded below ("below"), above ("above") or both ("both")."""
        below = bool(np.all(np.isfinite(self.low)))
        above = bool(np.all(np.isfinite(self.high)))
        if manner == "both":
            return below and above
        if manner == "below":
            return below
        if manner == "above":
            return above
        raise ValueError(f"manner '{manner}' is unknown; valid: both, below, above")

    def sample(self):
        """A random element: uniform where both bounds are finite, normal where none is, and
        shifted exponential where one is (as Gymnasium samples)."""
        rng = self.np_random
        low = self.low.astype(np.float64)
        high = self.high.astype(np.float64)
        lo_ok, hi_ok = np.isfinite(low), np.isfinite(high)
        if lo_ok.all() and hi_ok.all():
            return rng.uniform(low, high).astype(self.dtype)
        out = rng.normal(size=self.shape)
        both = lo_ok & hi_ok
        out[both] = rng.uniform(low[both], high[both])
        only_lo = lo_ok & ~hi_ok
        out[only_lo] = low[only_lo] + rng.exponential(size=int(only_lo.sum()))
        only_hi = hi_ok & ~lo_ok
        out[only_hi] = high[only_hi] - rng.exponential(size=int(only_hi.sum()))
        return out.astype(self.dtype)

    def contains(self, x):
        """Whether ``x`` has this shape, a castable dtype and lies within the bounds."""
        if not isinstance(x, np.ndarray):
            try:
                x = np.asarray(x, dtype=self.dtype)
            except (ValueError, TypeError):
                return False
        if x.shape != self.shape or not np.can_cast(x.dtype, self.dtype, casting="same_kind"):
            return False
        return bool(np.all(x >= self.low) and np.all(x <= self.high))

    def __contains__(self, x):
        return self.contains(x)

    def __eq__(self, other):
        return (isinstance(other, Box) and self.shape == other.shape
                and self.dtype == other.dtype and np.array_equal(self.low, other.low)
                and np.array_equal(self.high, other.high))

    def __repr__(self):
        def bound(a):
            return str(a.flat[0]) if a.size and np.all(a == a.flat[0]) else str(a)
        return f"Box({bound(self.low)}, {bound(self.high)}, {self.shape}, {self.dtype})"
