#ifndef ddcontact_relaxation_h
#define ddcontact_relaxation_h

#include <deal.II/lac/vector.h>

#include <ddcontact/solvers/contact_solver_parameters.h>

#include <deque>
#include <functional>
#include <memory>

namespace ddcontact
{
  using namespace dealii;

  /**
   * The relaxation step of the DD (21): from the iterate x = u^k and the
   * map value g = u~^{k+1} (the body solutions loaded by the pressure of
   * u^k), the next iterate u^{k+1}. Each strategy keeps its own history;
   * reset() forgets it (a new Uzawa phase or a new mesh changes the map).
   *
   * The vectors are the iterate's entries as this process holds them
   * (all of them on one process); the inner product that Aitken and
   * Anderson take of them is set by the solver (set_inner_product()), so
   * that a body whose vectors are distributed over processes adds every
   * process's part. Every other operation is entrywise.
   */
  class Relaxation
  {
  public:
    using InnerProduct =
      std::function<double(const Vector<double> &, const Vector<double> &)>;

    explicit Relaxation(const double gamma);

    virtual ~Relaxation() = default;

    /** Forget the history. */
    virtual void
    reset()
    {
    }

    /** u^{k+1} from x = u^k and g = u~^{k+1}. */
    virtual Vector<double>
    update(const Vector<double> &x, const Vector<double> &g) = 0;

    /** The current relaxation parameter gamma (dynamic for Aitken). */
    double
    get_gamma() const
    {
      return gamma;
    }

    void
    set_gamma(const double new_gamma)
    {
      gamma = new_gamma;
    }

    /** x . y for the strategies (default: ordered_dot(), all entries on
     * this process). */
    void
    set_inner_product(InnerProduct product)
    {
      inner = std::move(product);
    }

  protected:
    double       gamma;
    InnerProduct inner;
  };

  /** The paper's fixed relaxation (21): u^{k+1} = u^k + gamma (g - u^k). */
  class FixedRelaxation : public Relaxation
  {
  public:
    using Relaxation::Relaxation;

    Vector<double>
    update(const Vector<double> &x, const Vector<double> &g) override;
  };

  /** Aitken's dynamic relaxation: gamma from the secant of the last two
   * residuals f = g - x. */
  class AitkenRelaxation : public Relaxation
  {
  public:
    using Relaxation::Relaxation;

    void
    reset() override;

    Vector<double>
    update(const Vector<double> &x, const Vector<double> &g) override;

  private:
    Vector<double> previous_residual;
    // Whether previous_residual belongs to this phase: a flag, the same
    // on every process, since the sizes of the vectors are not (a process
    // that owns no entry holds empty ones) and the branch takes inner
    // products, which may be collective.
    bool has_previous = false;
  };

  /** Anderson acceleration (type II) of depth m: the combination of the
   * last m map values whose linearised residual is smallest (GMRES on a
   * linear fixed-point map), by a filtered QR of the residual differences. */
  class AndersonRelaxation : public Relaxation
  {
  public:
    AndersonRelaxation(double gamma, unsigned int depth);

    void
    reset() override;

    Vector<double>
    update(const Vector<double> &x, const Vector<double> &g) override;

  private:
    const unsigned int         depth;
    Vector<double>             previous_residual, previous_g;
    std::deque<Vector<double>> delta_f, delta_g;
    // Whether the previous_ vectors belong to this phase (see
    // AitkenRelaxation).
    bool has_previous = false;
  };

  /** The strategy of Contact solver/Domain decomposition/Relaxation ("auto" is
   * the fixed relaxation, its gamma set by the solver from an estimate). */
  std::unique_ptr<Relaxation>
  make_relaxation(const DomainDecompositionParameters &parameters);
} // namespace ddcontact

#endif
