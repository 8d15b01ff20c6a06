// DESCRIPTION: summary.json's JSON (nlohmann's ordered_json): NaN and
// infinities are written as null, keys keep the order they were set in
// (also when one is set again), nested arrays and objects, and the file
// write_json_file() writes reads back to the same values
#include <ddcontact/io/json.h>

#include "test_tools.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace ddcontact;
using namespace ddcontact::testing;

int
main(int argc, char **argv)
{
  (void)argc;
  (void)argv;

  // 1. Non-finite numbers: null, never "nan" or "inf". (The keys are
  // single letters so that only a value could spell these.)
  {
    Json j;
    j["q"]                 = std::numeric_limits<double>::quiet_NaN();
    j["p"]                 = std::numeric_limits<double>::infinity();
    j["m"]                 = -std::numeric_limits<double>::infinity();
    j["n"]                 = Json::array({1.5, std::nan(""), -2.});
    const std::string text = j.dump(2);
    std::cout << text << std::endl;
    const Json back = Json::parse(text);
    check(back.at("q").is_null() && back.at("p").is_null() &&
            back.at("m").is_null(),
          "NaN, inf and -inf are written as null");
    check(back.at("n").at(1).is_null() &&
            back.at("n").at(0).get<double>() == 1.5 &&
            back.at("n").at(2).get<double>() == -2.,
          "and inside an array, between finite numbers");
    check(text.find("nan") == std::string::npos &&
            text.find("inf") == std::string::npos &&
            text.find("NaN") == std::string::npos,
          "no nan or inf token in the text");
  }

  // 2. Key order: the order of insertion, not alphabetical; setting a key
  // again keeps its place.
  {
    Json j;
    j["scene"]  = "s";
    j["status"] = "converged";
    j["bodies"] = Json::array();
    j["alpha"]  = 1;
    j["status"] = "stalled";
    std::string keys;
    for (const auto &[key, value] : j.items())
      keys += key + ' ';
    check(keys == "scene status bodies alpha ", "keys in insertion order");
    check(j.at("status") == "stalled", "a key set again has its new value");
    const std::string text = j.dump();
    check(text.find("\"scene\"") < text.find("\"status\"") &&
            text.find("\"status\"") < text.find("\"bodies\"") &&
            text.find("\"bodies\"") < text.find("\"alpha\""),
          "and written in that order");
  }

  // 3. A nested value like summary.json's, written to a file and read
  // back.
  Json summary;
  summary["scene"]  = "paper_two_bodies";
  summary["status"] = "converged";
  Json body;
  body["name"]             = "omega1";
  body["cells"]            = 2048u;
  body["distributed_mesh"] = false;
  body["dofs"]             = static_cast<unsigned long>(2210);
  body["strain_energy"]    = 0.077904646361914034;
  summary["bodies"]        = Json::array({body});
  summary["theta"]         = Json::array({2.3809523809523811e-07});
  summary["force"]         = Json::array({Json::array({0., 289.30550675566718}),
                                          Json::array({0., -289.30550675566718})});
  summary["delta"]         = 0.05;
  summary["tiny"]          = 4.9406564584124654e-324;
  summary["huge"]          = 1.7976931348623157e308;
  summary["unicode"]       = "σ_n \"quoted\"\n";
  summary["empty"]         = Json::array();
  summary["empty_obj"]     = Json::object();
  summary["wall_time_s"]   = std::numeric_limits<double>::quiet_NaN();

  const std::string filename = "json_test_output.json";
  write_json_file(summary, filename);
  std::ifstream     in(filename);
  std::stringstream text;
  text << in.rdbuf();
  std::cout << text.str();
  const Json back = Json::parse(text.str());

  check(back.at("wall_time_s").is_null(), "NaN in the file is null");
  Json expected           = summary;
  expected["wall_time_s"] = nullptr;
  check(back == expected, "the file reads back to the same values");
  check(back.at("bodies").at(0).at("strain_energy").get<double>() ==
            0.077904646361914034 &&
          back.at("tiny").get<double>() == 4.9406564584124654e-324 &&
          back.at("huge").get<double>() == 1.7976931348623157e308,
        "doubles round-trip exactly");
  check(back.at("force").at(1).at(1).get<double>() == -289.30550675566718,
        "nested arrays");
  check(back.at("bodies").at(0).at("cells").get<unsigned int>() == 2048 &&
          back.at("bodies").at(0).at("dofs").get<unsigned long>() == 2210 &&
          !back.at("bodies").at(0).at("distributed_mesh").get<bool>(),
        "integers and booleans in an object in an array");
  check(back.at("unicode").get<std::string>() == "σ_n \"quoted\"\n",
        "strings with quotes, newlines and UTF-8");
  std::string keys;
  for (const auto &[key, value] : back.items())
    keys += key + ' ';
  check(keys == "scene status bodies theta force delta tiny huge unicode "
                "empty empty_obj wall_time_s ",
        "the file keeps the key order");
  check(text.str().back() == '\n', "the file ends with a newline");
  std::remove(filename.c_str());

  // 4. A file that cannot be written: an error naming it.
  try
  {
    write_json_file(summary, "no/such/directory/summary.json");
    check(false, "writing into a missing directory throws");
  }
  catch (const std::runtime_error &e)
  {
    check(std::string(e.what()).find("no/such/directory/summary.json") !=
            std::string::npos,
          "writing into a missing directory throws, naming the file");
  }

  return report();
}
