// DESCRIPTION: the boundary-condition grammar of a body (Dirichlet
// "id: components: expr_x; expr_y | ...", Neumann "id: expr_x; expr_y |
// ...", Contact ids "id, id", Body force "expr_x; expr_y") read from a
// scene file: the ids, component masks and function values of valid
// entries against the expressions by hand, and every malformed entry
// refused by an InputError that names the body, the entry and the fault
#include <deal.II/lac/vector.h>

#include <ddcontact/body/boundary_conditions.h>
#include <ddcontact/parameters.h>

#include "test_tools.h"

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace ddcontact;
using namespace ddcontact::testing;

namespace
{
  /** One body "block" on (0, 2) x (0, 1) (rectangle ids: 0 left, 1
   * right, 2 bottom, 3 top), constants p = 2 and Delta = 0.25. */
  const std::string scene_file = "boundary_conditions_scene.prm";

  void
  write_scene()
  {
    std::ofstream out(scene_file);
    out << "set Scene name       = boundary_conditions\n"
        << "set Output directory = boundary_conditions_output\n"
        << "set Bodies           = block\n"
        << "set Constants        = p=2, Delta=0.25\n"
        << "subsection Adaptation\n"
        << "  set Mode = none\n"
        << "end\n"
        << "subsection Body block\n"
        << "  subsection Mesh\n"
        << "    set Corner 1 = 0, 0\n"
        << "    set Corner 2 = 2, 1\n"
        << "  end\n"
        << "  subsection Boundary conditions\n"
        << "    set Dirichlet   = 2: xy: 0; 0 | 3: y: 0; -Delta\n"
        << "    set Neumann     = 1: 0; -p*x\n"
        << "    set Contact ids = 0\n"
        << "    set Body force  = x*y; -1\n"
        << "  end\n"
        << "end\n";
  }

  /** "Body block/Boundary conditions/<entry>=<value>". */
  std::string
  set(const std::string &entry, const std::string &value)
  {
    return "Body block/Boundary conditions/" + entry + "=" + value;
  }

  /** The conditions of the scene with @p overrides, as the body gets
   * them. */
  BoundaryConditions<2>
  read(const std::vector<std::string> &overrides)
  {
    const ParameterReader reader(scene_file, overrides);
    return make_boundary_conditions(reader.scene().bodies.at(0),
                                    reader.scene().constants);
  }

  /** Whether @p f has the value (@p v_x, @p v_y) at @p x, to round-off. */
  bool
  value_is(const Function<2> &f,
           const Point<2>    &x,
           const double       v_x,
           const double       v_y)
  {
    Vector<double> v(2);
    f.vector_value(x, v);
    return std::abs(v(0) - v_x) < 1e-14 && std::abs(v(1) - v_y) < 1e-14;
  }

  bool
  mask_is(const ComponentMask &mask, const bool x, const bool y)
  {
    return mask.size() == 2 && mask[0] == x && mask[1] == y;
  }

  /** The scene with @p entry = @p value must be refused by an InputError
   * whose message names the body, the entry and each of @p fragments. */
  void
  check_refused(const std::string              &entry,
                const std::string              &value,
                const std::vector<std::string> &fragments)
  {
    const std::string message = error_message<InputError>(
      [&] { ParameterReader reader(scene_file, {set(entry, value)}); });
    std::vector<std::string> expected = {"Body block", entry};
    expected.insert(expected.end(), fragments.begin(), fragments.end());
    std::cout << "  " << entry << " = '" << value << "': " << message
              << std::endl;
    check(message_names(message, expected),
          entry + " = '" + value + "' refused, naming the entry");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  write_scene();

  // The scene as written: both components held on the bottom (2), the
  // top (3) pushed down by Delta = 0.25 in y only, the traction
  // (0, -p x) = (0, -2 x) on the right (1), contact on the left (0), the
  // body force (x y, -1).
  std::cout << "Valid entries:" << std::endl;
  {
    const auto bc = read({});
    check(bc.dirichlet.size() == 2 && bc.dirichlet.count(2) &&
            bc.dirichlet.count(3),
          "Dirichlet on ids 2 and 3");
    check(mask_is(bc.dirichlet.at(2).mask, true, true) &&
            mask_is(bc.dirichlet.at(3).mask, false, true),
          "components: xy on 2, y on 3");
    check(value_is(*bc.dirichlet.at(2).displacement, {0.3, 0.}, 0., 0.),
          "id 2 at (0.3, 0): (0, 0)");
    check(value_is(*bc.dirichlet.at(3).displacement, {0.3, 1.}, 0., -0.25),
          "id 3 at (0.3, 1): (0, -Delta) = (0, -0.25)");
    check(bc.neumann.size() == 1 && bc.neumann.count(1) &&
            value_is(*bc.neumann.at(1), {2., 0.5}, 0., -4.),
          "Neumann on id 1, at (2, 0.5): (0, -p x) = (0, -4)");
    check(bc.contact == std::set<types::boundary_id>{0}, "Contact ids: {0}");
    check(bc.body_force && value_is(*bc.body_force, {0.3, 0.7}, 0.21, -1.),
          "Body force at (0.3, 0.7): (x y, -1) = (0.21, -1)");
  }
  // The x component alone, spaces anywhere, a Neumann condition on two
  // ids, no contact.
  {
    const auto bc = read({set("Dirichlet", "  0 : x :0.5*y ; 7|2:y:0;x^2 "),
                          set("Neumann", "1: 0; -p*x | 3 : p*y ; 0"),
                          set("Contact ids", "")});
    check(bc.dirichlet.size() == 2 &&
            mask_is(bc.dirichlet.at(0).mask, true, false) &&
            mask_is(bc.dirichlet.at(2).mask, false, true),
          "spaces ignored: x on 0, y on 2");
    check(value_is(*bc.dirichlet.at(0).displacement, {0., 0.6}, 0.3, 7.),
          "id 0 at (0, 0.6): (0.5 y, 7) = (0.3, 7)");
    check(value_is(*bc.dirichlet.at(2).displacement, {1.5, 0.}, 0., 2.25),
          "id 2 at (1.5, 0): (0, x^2) = (0, 2.25)");
    check(bc.neumann.size() == 2 &&
            value_is(*bc.neumann.at(3), {1., 1.}, 2., 0.),
          "Neumann on 1 and 3; id 3 at (1, 1): (p y, 0) = (2, 0)");
    check(bc.contact.empty(), "no contact ids");
  }
  // Several contact ids, no Neumann condition and no body force.
  {
    const auto bc = read({set("Dirichlet", "2: xy: 0; 0"),
                          set("Neumann", ""),
                          set("Contact ids", "0, 3,1"),
                          set("Body force", " ")});
    check(bc.contact == std::set<types::boundary_id>{0, 1, 3},
          "Contact ids '0, 3,1': {0, 1, 3}");
    check(bc.neumann.empty(), "no Neumann condition");
    check(!bc.body_force, "a blank Body force is none");
  }

  // A body without Dirichlet conditions, or with one component only, is
  // floating (held by contact; tests/floating_body.cc): the grammar takes it.
  {
    const auto none = read({set("Dirichlet", "")});
    check(none.dirichlet.empty(),
          "an empty Dirichlet entry is read (floating)");
    const auto roller = read({set("Dirichlet", "3: y: 0; -Delta")});
    check(roller.dirichlet.size() == 1 &&
            mask_is(roller.dirichlet.at(3).mask, false, true),
          "a single y component is read (free to slide in x)");
  }

  std::cout << "Malformed entries:" << std::endl;
  const std::string form = "is not 'id: components: expr_x; expr_y'";
  check_refused("Dirichlet", "2 xy: 0; 0", {"'2 xy: 0; 0'", form});
  check_refused("Dirichlet", "2: xy 0; 0", {"'2: xy 0; 0'", form});
  check_refused("Dirichlet", "2: z: 0; 0", {"components 'z'"});
  check_refused("Dirichlet", "2: xy: 0", {"2 expression(s)"});
  check_refused("Dirichlet", "2: xy: 0; 0; 1", {"2 expression(s)"});
  check_refused("Dirichlet", "2: xy: 0; sin(", {"cannot parse", "0; sin("});
  check_refused("Dirichlet", "2: xy: 0; q*x", {"0; q*x", "'q'", "not defined"});
  check_refused(
    "Dirichlet", "2: x: 0; 0 | 2: y: 0; 0", {"boundary id 2 appears twice"});
  check_refused("Dirichlet", "two: xy: 0; 0", {"'two'", "not a boundary id"});
  check_refused("Dirichlet", "-1: xy: 0; 0", {"not a boundary id"});
  check_refused("Neumann", "1 0; -p*x", {"is not 'id: expr_x; expr_y'"});
  check_refused("Neumann", "1: -p*x", {"2 expression(s)"});
  check_refused("Neumann", "1: 0; -p*", {"cannot parse", "0; -p*"});
  check_refused(
    "Neumann",
    "2: 0; 1",
    {"boundary id 2 has a Dirichlet condition on y", "must be 0, not '1'"});
  check_refused("Neumann",
                "1: 0; 0 | 1: 0; 1",
                {"boundary id 1 already has a boundary condition"});
  check_refused("Contact ids", "1", {"boundary id 1 already has"});
  // Contact ids is checked by Patterns::List(Integer(0, 254)) when the
  // file is read: deal.II's message gives the value and the pattern.
  check_refused("Contact ids", "0, zero", {"'0, zero'", "'zero': it is not"});
  check_refused("Body force", "1", {"2 expression(s)"});
  check_refused("Body force", "x*; 0", {"cannot parse 'x*; 0'"});

  return report();
}
