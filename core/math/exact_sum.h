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
    const Pair second = two_sum(first.sum, first.error + lo_);
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

  double hi_ = 0, lo_ = 0;
};

}  // namespace caustica
