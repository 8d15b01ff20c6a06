#ifndef ddcontact_parameters_h
#define ddcontact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/body/material.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ddcontact
{
  using namespace dealii;

  /**
   * An error in the user's input: a parameter, a file or a value. main()
   * prints its message as one line and exits with a non-zero code. The
   * message names the parameter (with its section) or the file.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /** Named constants usable in every expression ("r0=1e-3, Delta=..."). */
  using Constants = std::map<std::string, double>;

  /** Contact pair/Gap type: f_n from an expression, or the distance to
   * the orthogonal projection on S_2. */
  enum class GapType
  {
    expression,
    geometric
  };

  /** Contact pair/Penalty type: theta = c H / E_1, or theta itself. */
  enum class PenaltyType
  {
    relative,
    absolute
  };

  /** Body/Solver/Type: a direct factorization, or CG with AMG. */
  enum class BodySolverType
  {
    direct,
    cg_amg
  };

  /**
   * Everything that describes one elastic body: its mesh, its element, its
   * material and its boundary conditions by boundary id. Declared in the
   * subsection "Body <name>" of the parameter file, one per name listed in
   * "Bodies".
   */
  struct BodyParameters
  {
    std::string name;

    // Mesh
    std::string               mesh_type = "rectangle"; // "rectangle" or "file"
    Point<2>                  corner_1{0., 0.};
    Point<2>                  corner_2{1., 1.};
    std::vector<unsigned int> subdivisions{1, 1};
    std::string               mesh_file;
    unsigned int              initial_refinement = 0;
    std::vector<double>       refinement_box; // x0, y0, x1, y1, or empty
    unsigned int              box_refinement = 0;

    // Element
    std::string  cell_type = "quadrilateral"; // or "triangle"
    unsigned int degree    = 1;
    // "full", or "reduced": the volumetric term lambda div u div v of (11)
    // on one Gauss point per Q1 cell (selective reduced integration).
    std::string volumetric_integration = "full";

    Material material;

    // Boundary conditions as written in the file, parsed by
    // make_boundary_conditions() once the constants are known.
    std::string dirichlet;
    std::string neumann;
    std::string contact_ids;
    std::string body_force;

    // Linear solver of the body problem (20).
    BodySolverType solver                = BodySolverType::direct;
    double         solver_tolerance      = 1e-12;
    unsigned int   solver_max_iterations = 10000;

    static void
    declare(ParameterHandler &prm);

    /** Read from the current subsection; checks values and throws
     * InputError naming "Body <name>/<entry>". */
    void
    parse(ParameterHandler &prm);

    /** "Body <name>/" for error messages. */
    std::string
    section() const
    {
      return "Body " + name;
    }
  };

  /**
   * A contact pair: zone S_1 (boundary id of body 1, where the contact
   * integral is computed) facing S_2 (boundary id of body 2). Declared in
   * "Contact pair <name>", one per name listed in "Contact pairs".
   */
  struct ContactPairParameters
  {
    std::string  name;
    std::string  body_1, body_2;
    unsigned int boundary_id_1 = 0, boundary_id_2 = 0;
    GapType      gap_type       = GapType::expression;
    std::string  gap_expression = "0";
    PenaltyType  penalty_type   = PenaltyType::relative;
    double       penalty        = 0.05; // c, or theta itself
    double       thickness      = 0;    // H; 0: from body 1's mesh
    unsigned int n_gauss        = 3;    // Gauss points per piece

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };

  /**
   * The domain decomposition (20)-(21) and its stopping tests, in the
   * subsection "Domain decomposition".
   */
  /** Domain decomposition/Solver: the DD (20)-(21), or the monolithic
   * semismooth Newton method on (16). */
  enum class ContactSolverType
  {
    dd,
    monolithic
  };

  /** Domain decomposition/Relaxation: the paper's fixed gamma of (21),
   * the optimal fixed gamma estimated at the start ("auto"), Aitken or
   * Anderson. */
  enum class RelaxationType
  {
    fixed,
    automatic,
    aitken,
    anderson
  };

  /** Domain decomposition/Stopping test. */
  enum class StoppingTest
  {
    residual, // u~^{k+1} - u^k on S
    paper,    // the paper's increment test with eps_u
    both      // either
  };

  /** Domain decomposition/Initial guess. */
  enum class InitialGuess
  {
    zero,
    elastic_layer // "winkler"
  };

  /** Adaptation/Mode: none; combined: one DD step (20)-(21) and one
   * adaptation step per cycle (Fig. 2); nested: DD to convergence on each
   * mesh, then adapt; uniform: DD to convergence, then refine every
   * cell. */
  enum class AdaptationMode
  {
    none,
    combined,
    nested,
    uniform
  };

  /** Adaptation/Estimator: eta_FB of (27) as printed; the local RMS stress
   * error relative to the global RMS stress; Kelly's, the baseline. */
  enum class EstimatorType
  {
    fem_bem,
    fem_bem_scaled,
    kelly
  };

  /** Adaptation/Marking: eta > delta as in (27), a fixed fraction, or
   * Doerfler's bulk criterion. */
  enum class MarkingType
  {
    threshold,
    fraction,
    doerfler
  };

  /** The entry value of an option ("fixed", "auto", "fem-bem-scaled", ...),
   * as summary.json and the messages write it. */
  std::string
  to_string(RelaxationType value);
  std::string
  to_string(AdaptationMode value);
  std::string
  to_string(EstimatorType value);
  std::string
  to_string(MarkingType value);

  struct DDParameters
  {
    ContactSolverType solver         = ContactSolverType::dd;
    RelaxationType    relaxation     = RelaxationType::fixed;
    double            gamma          = 0.02; // gamma of (21)
    unsigned int      anderson_depth = 8;
    StoppingTest      stopping       = StoppingTest::residual;
    double            eps_u          = 1.5e-3; // the paper's increment test
    double            eps_residual   = 1e-8;   // test on u~^{k+1} - u^k
    unsigned int      max_iterations = 5000;
    InitialGuess      initial_guess  = InitialGuess::elastic_layer;
    bool              augmented_lagrangian  = false;
    double            al_tolerance          = 1e-3; // penetration / approach
    unsigned int      al_max_updates        = 30;
    bool              write_every_iteration = false;
    bool              print_every_iteration = false; // Output/Verbosity = full
    unsigned int      n_newton              = 50;

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };

  /**
   * h-adaptivity and the combined algorithm (sections 4-5 of the paper
   * README), in the subsection "Adaptation".
   */
  struct AdaptationParameters
  {
    AdaptationMode           mode = AdaptationMode::none;
    std::vector<std::string> bodies; // the adapted bodies
    EstimatorType            estimator        = EstimatorType::fem_bem;
    MarkingType              marking          = MarkingType::threshold;
    double                   delta            = 0.1; // threshold of (27)
    double                   fraction         = 0.3;
    unsigned int             max_cycles       = 50;
    unsigned int             max_level        = 10;
    unsigned int             max_cells        = 200000;
    bool                     write_every_mesh = true;

    bool
    enabled() const
    {
      return mode != AdaptationMode::none;
    }

    static void
    declare(ParameterHandler &prm);

    void
    parse(ParameterHandler &prm);
  };

  /** A point at which displacement and stress of one body are reported. */
  struct ReportPoint
  {
    std::string body;
    Point<2>    x;
  };

  /**
   * Runs on several MPI processes, in the subsection "Parallel": which
   * processes solve which body (BodyDistribution).
   */
  struct ParallelParameters
  {
    /** "auto", "all" or "list" (the groups below). */
    std::string mode = "auto";
    /** With mode "list": the processes (world ranks, ascending) that solve
     * every body. */
    std::map<std::string, std::vector<unsigned int>> body_groups;
    /** "auto", "shared" or "distributed": how the mesh of a body that
     * several processes solve is split (see distributed_mesh()). */
    std::string mesh = "auto";

    /**
     * Whether the bodies' meshes are partitioned over process groups
     * (parallel::shared::Triangulation on MPI_COMM_WORLD, a distributed
     * matrix and solver on every group with more than one process): with
     * "all", with a list in which a body has several processes, and with
     * "auto" when there are more processes than bodies. Otherwise every
     * body is solved whole on one process (or there is one process).
     */
    bool
    process_groups(unsigned int n_processes, unsigned int n_bodies) const;

    /**
     * Whether @p body gets a parallel::distributed::Triangulation (p4est):
     * each process then keeps only its own cells and a ghost layer, so
     * the mesh memory shrinks with the processes. That needs a body of
     * quadrilaterals solved by every process ("all", or a list giving it
     * every process: the p4est forest lives on MPI_COMM_WORLD). "auto"
     * takes it wherever it is possible, "shared" never.
     */
    bool
    distributed_mesh(const BodyParameters &body,
                     unsigned int          n_processes) const;

    static void
    declare(ParameterHandler &prm);

    /** Checks the names against @p body_names and the processes against
     * the size of MPI_COMM_WORLD. */
    void
    parse(ParameterHandler &prm, const std::vector<std::string> &body_names);
  };

  /**
   * The top level of a parameter file: the scene's name, where results go,
   * which bodies exist (each with its own "Body <name>" subsection), named
   * constants for expressions, and output options.
   */
  struct SceneParameters
  {
    std::string              scene_name       = "scene";
    std::string              output_directory = "output";
    std::vector<std::string> body_names;
    Constants                constants;
    std::vector<ReportPoint> points;
    bool                     write_vtu = true;
    unsigned int             n_threads = 0; // 0 = all cores

    std::vector<BodyParameters>        bodies;
    std::vector<ContactPairParameters> contact_pairs;
    DDParameters                       dd;
    AdaptationParameters               adaptation;
    ParallelParameters                 parallel;

    /** Declare the scene entries and, for each name, a body subsection
     * and a contact pair subsection. */
    static void
    declare(ParameterHandler               &prm,
            const std::vector<std::string> &bodies,
            const std::vector<std::string> &pairs = {});

    void
    parse(ParameterHandler &prm);
  };

  /**
   * Reads a parameter file the way the executable does: a first pass
   * learns the names of the bodies, then all subsections are declared and
   * the file is parsed strictly (an unknown entry is an error). Overrides
   * "Section/Entry=value" are applied after the file. Every failure is an
   * InputError naming the file or the entry.
   */
  class ParameterReader
  {
  public:
    ParameterReader(const std::string              &filename,
                    const std::vector<std::string> &overrides);

    /** The scene as read, checked. */
    const SceneParameters &
    scene() const
    {
      return scene_parameters;
    }

    /** Print all entries with their documentation (and current values). */
    void
    print(std::ostream &out) const;

    /** The parameters as used, to copy into the output directory. */
    void
    write_used(const std::string &filename) const;

    /** Declared but empty: for --print-parameters without a file. */
    static void
    print_defaults(std::ostream &out);

  private:
    mutable ParameterHandler prm;
    SceneParameters          scene_parameters;
  };

  /** Refuse a body, pair or scene name that is not safe as part of a file
   * name; `what` names the entry. */
  void
  check_name(const std::string &name, const std::string &what);

  /** The contents of a regular file of at most @p max_bytes, read without
   * reading further (devices and pipes are refused); `what` names the
   * file's role in errors ("parameter file", "Body a/Mesh/File"). */
  std::string
  read_bounded_file(const std::string &filename,
                    std::size_t        max_bytes,
                    const std::string &what);

  /** Parse "x1, x2" into a point; `what` names the entry in errors. */
  Point<2>
  parse_point(const std::string &text, const std::string &what);

  /** Parse "name=value, name=value". */
  Constants
  parse_constants(const std::string &text, const std::string &what);

  /**
   * Turn the boundary-condition entries of a body into functions:
   *  - Dirichlet: "id: components: expr_x; expr_y | id: ...", components
   *    one of x, y, xy (e.g. "0: xy: 0; 0 | 3: y: 0; -Delta");
   *  - Neumann:   "id: expr_x; expr_y | ..." (traction, force per length);
   *  - Contact ids: "3, 4";
   *  - Body force: "expr_x; expr_y" or empty.
   * Expressions are in x, y and the scene's constants.
   */
  BoundaryConditions<2>
  make_boundary_conditions(const BodyParameters &body,
                           const Constants      &constants);

  /** A vector-valued FunctionParser in x, y, checked; `what` names the
   * entry in the error message if the expression does not parse. */
  std::shared_ptr<Function<2>>
  make_function(const std::string &expression,
                unsigned int       n_components,
                const Constants   &constants,
                const std::string &what);
} // namespace ddcontact

#endif
