#pragma once

namespace caustica {

// A running sum of doubles kept as the pair hi + lo: hi is the sum rounded
// to the nearest double, lo what that rounding left out (a double-double,
// updated with Knuth's error-free TwoSum). As long as no partial sum
// exceeds 2^52 times the smallest non-zero term in magnitude, nothing is
// ever rounded away, and the pair is the exact sum in its one canonical
// form: sums of the same terms are equal bit for bit whatever the order or
// grouping they were added in (threads, sample ranges, machines). Beyond
// that span the pair is still within 2^-105 of the sum, relatively.
class ExactSum {
 public:
  ExactSum() = default;
  // The pair another sum exported as value() and rest().
  static ExactSum from_parts(double value, double rest) {
    ExactSum s;
    s.add(value);
    s.add(rest);
    return s;
  }

  void add(double x) {
    const Pair first = two_sum(hi_, x);
    // The small part never outweighs the sum it joins: either fl(hi + x)
    // keeps at least half of |hi|, and the error and lo, each within half
    // an ulp of it or of hi, lie far below it, or hi and x cancelled, which
    // Sterbenz's lemma makes exact: then the error is 0 and the sum is zero
    // or a multiple of half an ulp of hi, no smaller than |lo|.
    const Pair second = fast_two_sum(first.sum, first.error + lo_);
    hi_ = second.sum;
    lo_ = second.error;
  }
  void add(const ExactSum& other) {
    add(other.hi_);
    add(other.lo_);
  }

  // The sum rounded to the nearest double.
  double value() const { return hi_; }
  // The sum minus value(), exactly.
  double rest() const { return lo_; }

 private:
  struct Pair {
    double sum, error;
  };
  // sum = fl(a + b) and error = a + b - sum exactly, for any a and b.
  static Pair two_sum(double a, double b) {
    const double sum = a + b;
    const double b_part = sum - a;
    return {sum, (a - (sum - b_part)) + (b - b_part)};
  }
  // The same for |a| >= |b| (Dekker's), in three operations instead of six.
  static Pair fast_two_sum(double a, double b) {
    const double sum = a + b;
    return {sum, (a - sum) + b};
  }

  double hi_ = 0, lo_ = 0;
};

}  // namespace caustica
