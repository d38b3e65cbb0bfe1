#include "grading/3_intersect/nearest_double.h"

#include <stdexcept>

namespace raystep {

namespace {

constexpr mpfr_prec_t kDoublePrecision = 53;

// MPFR emulates IEEE double when its exponent range is double's: [-1073, 1024] with 53 bits, and
// mpfr_subnormalize after each rounding (MPFR manual, "Exponent Related Functions").
class DoubleExponentRange {
  public:
    DoubleExponentRange() : emin_(mpfr_get_emin()), emax_(mpfr_get_emax()) {
        mpfr_set_emin(-1073);
        mpfr_set_emax(1024);
    }
    ~DoubleExponentRange() {
        mpfr_set_emin(emin_);
        mpfr_set_emax(emax_);
    }
    DoubleExponentRange(const DoubleExponentRange&) = delete;
    DoubleExponentRange& operator=(const DoubleExponentRange&) = delete;

  private:
    mpfr_exp_t emin_;
    mpfr_exp_t emax_;
};

// An MPFR number that frees itself.
class Real {
  public:
    explicit Real(mpfr_prec_t precision) { mpfr_init2(value_, precision); }
    ~Real() { mpfr_clear(value_); }
    Real(const Real&) = delete;
    Real& operator=(const Real&) = delete;
    mpfr_ptr get() { return value_; }

  private:
    mpfr_t value_;
};

// A rational that frees itself.
class Rational {
  public:
    Rational() { mpq_init(value_); }
    ~Rational() { mpq_clear(value_); }
    Rational(const Rational&) = delete;
    Rational& operator=(const Rational&) = delete;
    mpq_ptr get() { return value_; }

  private:
    mpq_t value_;
};

// The square root of q when it is a rational number, else false.
bool exact_square_root(mpq_srcptr q, mpq_ptr root) {
    if (mpq_sgn(q) < 0) return false;
    if (!mpz_perfect_square_p(mpq_numref(q)) || !mpz_perfect_square_p(mpq_denref(q))) return false;
    mpz_sqrt(mpq_numref(root), mpq_numref(q));
    mpz_sqrt(mpq_denref(root), mpq_denref(q));
    mpq_canonicalize(root);
    return true;
}

}  // namespace

double nearest_double(mpq_srcptr q) {
    const DoubleExponentRange range;
    Real x(kDoublePrecision);
    const int inexact = mpfr_set_q(x.get(), q, MPFR_RNDN);
    mpfr_subnormalize(x.get(), inexact, MPFR_RNDN);
    return mpfr_get_d(x.get(), MPFR_RNDN);
}

double nearest_double_of_root(mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, mpq_srcptr disc,
                              bool smaller) {
    if (mpq_sgn(a) <= 0 || mpq_sgn(disc) < 0) {
        throw std::invalid_argument("nearest_double_of_root: needs a > 0 and disc >= 0");
    }

    // A rational square root: the root is rational, and rounds like any rational.
    Rational root;
    if (exact_square_root(disc, root.get())) {
        Rational t;
        if (smaller) {
            mpq_neg(t.get(), root.get());
        } else {
            mpq_set(t.get(), root.get());
        }
        mpq_sub(t.get(), t.get(), b);
        mpq_div(t.get(), t.get(), a);
        return nearest_double(t.get());
    }

    // Irrational: never exactly a double or a midpoint between two, so rising precision decides.
    for (mpfr_prec_t p = 128;; p *= 2) {
        Real t(p);
        evaluate_root(t.get(), a, b, c, disc, smaller);
        if (mpfr_can_round(t.get(), p - 4, MPFR_RNDN, MPFR_RNDZ, kDoublePrecision + 1)) {
            // Certain to round as the exact root would. Results below 2.2e-308 are rounded to
            // the subnormal grid from this 53-bit value, a second rounding: off by at most one
            // subnormal step there.
            const DoubleExponentRange range;
            Real x(kDoublePrecision);
            const int inexact = mpfr_set(x.get(), t.get(), MPFR_RNDN);
            mpfr_subnormalize(x.get(), inexact, MPFR_RNDN);
            return mpfr_get_d(x.get(), MPFR_RNDN);
        }
        if (p > (1 << 16)) {
            throw std::runtime_error("nearest_double_of_root: no certain rounding at 65536 bits");
        }
    }
}

void evaluate_root(mpfr_ptr out, mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, mpq_srcptr disc,
                   bool smaller) {
    const mpfr_prec_t p = mpfr_get_prec(out);
    Real ra(p), rb(p), rc(p), rq(p);
    mpfr_set_q(ra.get(), a, MPFR_RNDN);
    mpfr_set_q(rb.get(), b, MPFR_RNDN);
    mpfr_set_q(rc.get(), c, MPFR_RNDN);
    mpfr_set_q(rq.get(), disc, MPFR_RNDN);
    mpfr_sqrt(rq.get(), rq.get(), MPFR_RNDN);
    const bool b_negative = mpq_sgn(b) < 0;
    if (b_negative) {
        mpfr_sub(rq.get(), rq.get(), rb.get(), MPFR_RNDN);  // q = sqrt(disc) - b > 0
    } else {
        mpfr_add(rq.get(), rq.get(), rb.get(), MPFR_RNDN);
        mpfr_neg(rq.get(), rq.get(), MPFR_RNDN);  // q = -(b + sqrt(disc)) <= 0
    }
    // For b < 0, q / a is the larger root; for b >= 0, the smaller.
    if (smaller != b_negative) {
        mpfr_div(out, rq.get(), ra.get(), MPFR_RNDN);
    } else {
        mpfr_div(out, rc.get(), rq.get(), MPFR_RNDN);
    }
}

}  // namespace raystep
