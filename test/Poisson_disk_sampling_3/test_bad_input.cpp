// Copyright (c) 2026 The Poisson_disk_sampling_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bad input gets its documented exception: never a crash, a hang or silent garbage.

#include "test_support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_integer.h>
#include <CGAL/MP_Float.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Simple_homogeneous.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>
#include <limits>

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

Mesh triangle()
{
  Mesh m;
  m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(1, 0, 0)), m.add_vertex(Point(0, 1, 0)));
  return m;
}

template <class NP>
void sample(const Mesh& m, const NP& np)
{
  std::vector<Point> out;
  PDS::sample_triangle_mesh(m, std::back_inserter(out), np);
}

// what a call throws as an exception of type E, or "no exception"
template <class E, class Call>
std::string what_thrown(Call&& call)
{
  try {
    call();
  } catch(const E& e) {
    return e.what();
  }
  return "no exception";
}

// The point types that the samplers refuse when the program is compiled (output_point()'s static
// assertion): a homogeneous kernel on Gmpz, or Cartesian ones on int or Gmpz, wrote the samples'
// coordinates truncated to integers, 1.41 apart for a minimum distance of 2.5. Those that hold
// doubles exactly pass: fields, exact binary floats, homogeneous kernels on them.
TEST(BadInput, PointTypesThatCannotHoldTheSamplesAreRefused)
{
  EXPECT_TRUE(PDS::internal::holds_doubles<K>());
  EXPECT_TRUE(PDS::internal::holds_doubles<CGAL::Exact_predicates_exact_constructions_kernel>());
  EXPECT_TRUE(PDS::internal::holds_doubles<CGAL::Simple_cartesian<double>>());
  EXPECT_TRUE(PDS::internal::holds_doubles<CGAL::Simple_cartesian<CGAL::Exact_rational>>());
  EXPECT_TRUE(PDS::internal::holds_doubles<CGAL::Simple_cartesian<CGAL::MP_Float>>());
  EXPECT_TRUE(PDS::internal::holds_doubles<CGAL::Simple_homogeneous<double>>());
  EXPECT_TRUE(PDS::internal::holds_doubles<CGAL::Simple_homogeneous<CGAL::Exact_rational>>());
  EXPECT_FALSE(PDS::internal::holds_doubles<CGAL::Simple_cartesian<float>>());
  EXPECT_FALSE(PDS::internal::holds_doubles<CGAL::Simple_cartesian<int>>());
  EXPECT_FALSE(PDS::internal::holds_doubles<CGAL::Simple_cartesian<CGAL::Exact_integer>>());
  EXPECT_FALSE(PDS::internal::holds_doubles<CGAL::Simple_homogeneous<CGAL::Exact_integer>>());
}

TEST(BadInput, EmptyMesh)
{
  EXPECT_THROW(sample(Mesh(), PDS::parameters::radius(0.1)), PDS::Invalid_input);
}

TEST(BadInput, MeshOfZeroArea)
{
  Mesh m;
  m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(1, 0, 0)), m.add_vertex(Point(2, 0, 0)));
  EXPECT_THROW(sample(m, PDS::parameters::radius(0.1)), PDS::Invalid_input);
  // nor is an empty set maximal on it: there is nothing to certify
  EXPECT_THROW(PDS::is_maximal(m, std::vector<Point>(), 0.2), PDS::Invalid_input);
}

TEST(BadInput, NonFiniteCoordinates)
{
  for(double bad : {nan, inf, -inf}) {
    Mesh m = triangle();
    m.point(*m.vertices().begin()) = Point(bad, 0, 0);
    EXPECT_THROW(sample(m, PDS::parameters::radius(0.1)), PDS::Invalid_input);
  }
  EXPECT_THROW(PDS::is_poisson_disk_set(std::vector<Point>{Point(nan, 0, 0)}, 1.), PDS::Invalid_input);
  std::vector<Point> out;
  EXPECT_THROW(PDS::sample_sphere(K::Sphere_3(Point(0, inf, 0), 1), std::back_inserter(out),
                                  PDS::parameters::radius(0.1)),
               PDS::Invalid_input);
}

TEST(BadInput, BadSizes)
{
  const Mesh m = triangle();
  for(double r : {0., -1., nan, inf}) {
    EXPECT_THROW(sample(m, PDS::parameters::radius(r)), PDS::Invalid_input) << r;
    EXPECT_THROW(sample(m, PDS::parameters::minimum_distance(r)), PDS::Invalid_input) << r;
    EXPECT_THROW(PDS::is_poisson_disk_set(std::vector<Point>(), r), PDS::Invalid_input) << r;
    EXPECT_THROW(PDS::is_maximal(m, std::vector<Point>(), r), PDS::Invalid_input) << r;
  }
  EXPECT_THROW(sample(m, PDS::parameters::number_of_points(0)), PDS::Invalid_input);
  // an infinite count or bound is called so, not "below 1"
  for(const std::string what :
      {what_thrown<PDS::Invalid_input>([&] { sample(m, PDS::parameters::number_of_points(inf)); }),
       what_thrown<PDS::Invalid_input>(
           [&] { sample(m, PDS::parameters::radius(0.1).maximum_number_of_points(inf)); })})
    EXPECT_NE(what.find("must be finite"), std::string::npos) << what;
  // finite, but twice it is not: the message says so, not that the radius is not finite
  const std::string overflow = what_thrown<PDS::Invalid_input>([&] { sample(m, PDS::parameters::radius(1e308)); });
  EXPECT_NE(overflow.find("2r overflows"), std::string::npos) << overflow;
  EXPECT_THROW(sample(m, CGAL::parameters::default_values()), PDS::Invalid_input) << "no size";
  EXPECT_THROW(sample(m, PDS::parameters::radius(0.1).minimum_distance(0.2)), PDS::Invalid_input) << "two sizes";
  EXPECT_THROW(sample(m, PDS::parameters::radius(0.1).number_of_points(10)), PDS::Invalid_input) << "two sizes";
}

// A parameter given twice is refused by name, not read once and dropped once unsaid: radius(0.1)
// .radius(0.05) sampled at 0.05.
TEST(BadInput, ParameterGivenTwice)
{
  const Mesh m = triangle();
  std::vector<Point> out;
  EXPECT_EQ(what_thrown<PDS::Invalid_input>([&] { sample(m, PDS::parameters::radius(0.1).radius(0.05)); }),
            "Poisson_disk_sampling_3: radius is given more than once");
  EXPECT_EQ(what_thrown<PDS::Invalid_input>([&] {
              sample(m, PDS::parameters::random_seed(1).minimum_distance(0.2).random_seed(2));
            }),
            "Poisson_disk_sampling_3: random_seed is given more than once");
  EXPECT_EQ(what_thrown<PDS::Invalid_input>([&] {
              PDS::sample_sphere(K::Sphere_3(CGAL::ORIGIN, 1), std::back_inserter(out),
                                 PDS::parameters::number_of_points(10).maximum_number_of_points(100)
                                     .maximum_number_of_points(1000));
            }),
            "Poisson_disk_sampling_3: maximum_number_of_points is given more than once");
  // each once, in any order, is fine
  EXPECT_EQ(what_thrown<PDS::Invalid_input>([&] {
              sample(m, PDS::parameters::random_seed(1).maximum_number_of_points(1000).minimum_distance(0.2));
            }),
            "no exception");
  // the certificate takes the parameters of the samplers, refused the same way (it used the last map)
  out.clear();
  PDS::sample_triangle_mesh(m, std::back_inserter(out), PDS::parameters::minimum_distance(0.2));
  const auto vpm = get(CGAL::vertex_point, m);
  EXPECT_EQ(what_thrown<PDS::Invalid_input>([&] {
              PDS::is_maximal(m, out, 0.2, PDS::parameters::vertex_point_map(vpm).vertex_point_map(vpm));
            }),
            "Poisson_disk_sampling_3: vertex_point_map is given more than once");
  EXPECT_EQ(what_thrown<PDS::Invalid_input>(
                [&] { PDS::is_maximal(m, out, 0.2, CGAL::parameters::vertex_point_map(vpm)); }),
            "no exception");
  // the sampling parameters, which it would ignore (the distance is its third argument), do not
  // compile there: the condition of its static_assert
  EXPECT_TRUE(PDS::internal::has_no_sampling_parameter<decltype(PDS::parameters::vertex_point_map(vpm))>());
  EXPECT_TRUE(PDS::internal::has_no_sampling_parameter<CGAL::parameters::Default_named_parameters>());
  EXPECT_FALSE(PDS::internal::has_no_sampling_parameter<decltype(PDS::parameters::radius(0.1))>());
  EXPECT_FALSE(PDS::internal::has_no_sampling_parameter<decltype(
                   PDS::parameters::vertex_point_map(vpm).random_seed(3))>());
  EXPECT_FALSE(PDS::internal::has_no_sampling_parameter<decltype(
                   PDS::parameters::geom_traits(K()).maximum_number_of_points(10))>());
}

// A seed is an integer from 0 to 2^64 - 1: a negative one was converted (-1 gave the points of
// 2^64 - 1) and is refused; seeds beyond 2^32 are seeds of their own.
TEST(BadInput, NegativeSeedsAreRefused)
{
  const Mesh m = triangle();
  EXPECT_THROW(sample(m, PDS::parameters::radius(0.1).random_seed(-1)), PDS::Invalid_input);
  EXPECT_THROW(sample(m, PDS::parameters::number_of_points(10).random_seed(std::int64_t(-5))), PDS::Invalid_input);
  std::vector<Point> a, b, c;
  PDS::sample_triangle_mesh(m, std::back_inserter(a), PDS::parameters::radius(0.05).random_seed(3));
  PDS::sample_triangle_mesh(m, std::back_inserter(b), PDS::parameters::radius(0.05).random_seed(std::int64_t(3)));
  PDS::sample_triangle_mesh(m, std::back_inserter(c),
                            PDS::parameters::radius(0.05).random_seed((std::uint64_t(1) << 40) + 3));
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

// The triangle model, counting the darts thrown on it.
struct Counting_darts : PDS::Triangle_fragment_traits_3
{
  static inline std::size_t darts = 0;
  explicit Counting_darts(const PDS::Triangle_fragment_traits_3& t) : PDS::Triangle_fragment_traits_3(t) {}
  template <class RandomGenerator>
  std::optional<Sample> random_sample(const Fragment& f, RandomGenerator& rng) const
  {
    ++darts;
    return PDS::Triangle_fragment_traits_3::random_sample(f, rng);
  }
};

TEST(BadInput, TooManyPointsIsRefusedBeforeAllocating)
{
  const Mesh m = triangle(); // area 0.5
  // area / (pi r^2) = 1.6e13 points: refused at once, not after filling memory
  EXPECT_THROW(sample(m, PDS::parameters::radius(1e-7)), PDS::Point_limit_exceeded);
  EXPECT_THROW(sample(m, PDS::parameters::radius(0.01).maximum_number_of_points(100)), PDS::Point_limit_exceeded);
  EXPECT_THROW(sample(m, PDS::parameters::number_of_points(200000000)), PDS::Point_limit_exceeded);
  // the same requests through the model of the triangle, counting its darts: none is thrown
  auto darts_before_refusal = [](const Mesh& mesh, const auto& np) {
    std::vector<Mesh::Face_index> face_of;
    const Counting_darts counting(PDS::internal::triangles_of_mesh(mesh, CGAL::parameters::default_values(), face_of));
    Counting_darts::darts = 0;
    std::vector<Counting_darts::Sample> out;
    EXPECT_THROW(PDS::sample_surface(counting, std::back_inserter(out), np), PDS::Point_limit_exceeded);
    return Counting_darts::darts;
  };
  EXPECT_EQ(darts_before_refusal(m, PDS::parameters::radius(1e-7)), 0u);
  EXPECT_EQ(darts_before_refusal(m, PDS::parameters::radius(0.01).maximum_number_of_points(100)), 0u);
  EXPECT_EQ(darts_before_refusal(m, PDS::parameters::number_of_points(200000000)), 0u);
  // where the estimate is below the bound and the points are not (a sliver 10^-6 wide: area / (pi r^2)
  // is 0.16, the points about 370), the run is stopped at the bound, after its darts
  Mesh sliver;
  sliver.add_face(sliver.add_vertex(Point(0, 0, 0)), sliver.add_vertex(Point(1, 0, 0)),
                  sliver.add_vertex(Point(1, 1e-6, 0)));
  EXPECT_GE(darts_before_refusal(sliver, PDS::parameters::radius(0.001).maximum_number_of_points(100)), 100u);
  // the estimate in the message: a whole number, or where that is not above the bound (it said
  // "about 100 ... exceeds maximum_number_of_points (100)"), the digits that show it is
  auto refusal = [&](double r) {
    return what_thrown<PDS::Point_limit_exceeded>(
        [&] { sample(m, PDS::parameters::radius(r).maximum_number_of_points(100)); });
  };
  EXPECT_NE(refusal(0.01).find("(about 1591, "), std::string::npos) << refusal(0.01);
  const double r = std::sqrt(0.5 / (3.14159265358979323846 * 100.4));
  EXPECT_NE(refusal(r).find("(about 100.4, "), std::string::npos) << refusal(r);
  // within the bound it works
  std::vector<Point> out;
  PDS::sample_triangle_mesh(m, std::back_inserter(out), PDS::parameters::radius(0.05).maximum_number_of_points(100));
  EXPECT_GT(out.size(), 10u);
}

// Many tiny separate triangles each need their own sample, beyond what the area predicts: the bound
// also holds while sampling.
TEST(BadInput, BoundHoldsWhileSampling)
{
  std::vector<Point> p;
  std::vector<std::array<std::size_t, 3>> t;
  for(std::size_t i = 0; i < 1000; ++i) {
    const double x = 10. * double(i);
    p.insert(p.end(), {Point(x, 0, 0), Point(x + 1e-3, 0, 0), Point(x, 1e-3, 0)});
    t.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  std::vector<Point> out;
  // the statistics say which distance the call was running when it threw (they were all zero)
  PDS::Sampling_statistics stats;
  EXPECT_THROW(PDS::sample_polygon_soup(p, t, std::back_inserter(out),
                                        PDS::parameters::minimum_distance(1.).maximum_number_of_points(500).statistics(
                                            std::ref(stats))),
               PDS::Point_limit_exceeded);
  EXPECT_EQ(stats.minimum_distance, 1.);
  EXPECT_EQ(stats.number_of_runs, 1u);
  out.clear();
  PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::minimum_distance(1.));
  EXPECT_EQ(out.size(), 1000u);
}

// Each call clears the statistics first: a call that throws before its first run (an empty mesh, a
// bad size, a bad sphere) left those of the call before it.
TEST(BadInput, StatisticsAreClearedByEachCall)
{
  const Mesh m = triangle();
  PDS::Sampling_statistics stats;
  const auto sampled = [&] {
    sample(m, PDS::parameters::number_of_points(50).random_seed(9).statistics(std::ref(stats)));
    ASSERT_GT(stats.number_of_runs, 0u);
    ASSERT_GT(stats.darts, 0u);
  };
  const auto cleared = [&](const char* what) {
    EXPECT_EQ(stats.minimum_distance, 0.) << what;
    EXPECT_EQ(stats.random_seed, 0u) << what;
    EXPECT_EQ(stats.number_of_runs, 0u) << what;
    EXPECT_EQ(stats.darts, 0u) << what;
  };
  std::vector<Point> out;
  sampled();
  EXPECT_THROW(sample(Mesh(), PDS::parameters::radius(0.1).statistics(std::ref(stats))), PDS::Invalid_input);
  cleared("empty mesh");
  sampled();
  EXPECT_THROW(sample(m, PDS::parameters::radius(-0.1).statistics(std::ref(stats))), PDS::Invalid_input);
  cleared("negative radius");
  sampled();
  const std::vector<Point> no_points;
  const std::vector<std::array<int, 3>> no_polygons;
  EXPECT_THROW(PDS::sample_polygon_soup(no_points, no_polygons, std::back_inserter(out),
                                        PDS::parameters::radius(0.1).statistics(std::ref(stats))),
               PDS::Invalid_input);
  cleared("empty soup");
  sampled();
  EXPECT_THROW(PDS::sample_sphere(K::Sphere_3(Point(0, inf, 0), 1), std::back_inserter(out),
                                  PDS::parameters::radius(0.1).statistics(std::ref(stats))),
               PDS::Invalid_input);
  cleared("bad sphere");
}

// Copies of a face count in the area as many times: a number_of_points search on them needs a
// distance at which area / (pi r^2), what its runs cost, is many times the points. Its runs are not
// refused by that estimate as a radius request is (on a flat surface it is 1.8 times the count), but
// the search takes no distance at which it exceeds four times the bound, and 64: 2,000 copies of a
// triangle held 900,000 fragments in wait to give 1,000 points under a bound of 5,000, where the
// radius mode refuses 3.5 million points. A surface folded closer than d, whose estimate goes past
// four times the bound only at a distance the search tries on its way, still gets its points.
TEST(BadInput, CountOnManyCopiesOfAFaceIsRefusedBeyondTheBound)
{
  const std::vector<Point> p = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  const std::vector<std::array<std::size_t, 3>> t(50, {0, 1, 2});
  std::vector<Point> out;
  const std::string what = what_thrown<PDS::Point_limit_exceeded>([&] {
    PDS::sample_polygon_soup(p, t, std::back_inserter(out),
                             PDS::parameters::number_of_points(1000).maximum_number_of_points(5000));
  });
  EXPECT_NE(what.find("exceed four times maximum_number_of_points (5000)"), std::string::npos) << what;
  EXPECT_NE(what.find("overlap"), std::string::npos) << what;
  // with room for them, the copies are sampled: a maximal set of the triangle, each point once
  out.clear();
  PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::number_of_points(1000));
  EXPECT_NEAR(double(out.size()), 1000., 10.);
  // and a single copy at the bound is not refused (its area / (pi r^2) is about 1,800)
  out.clear();
  PDS::sample_polygon_soup(p, std::vector<std::array<std::size_t, 3>>(1, {0, 1, 2}), std::back_inserter(out),
                           PDS::parameters::number_of_points(1000).maximum_number_of_points(1000));
  EXPECT_NEAR(double(out.size()), 1000., 10.);
  // A strip 1 long and 1 / 100 wide folded 100 times (area 2.69): the search's second distance,
  // 0.0281, has an estimate of 4,342, above 4,064; the search runs at 0.0291 instead, where it is
  // 4,064, and goes on to 1,000 points (998 at 0.0296 with seed 0). It was refused at 0.0281.
  std::vector<Point> folds;
  std::vector<std::array<std::size_t, 3>> strips;
  for(std::size_t i = 0; i <= 100; ++i) {
    const double x = 0.01 * double(i), z = i % 2 == 0 ? 0 : 0.025;
    folds.insert(folds.end(), {Point(x, 0, z), Point(x, 1, z)});
    if(i > 0) {
      const std::size_t a = 2 * i - 2, b = 2 * i - 1, c = 2 * i, e = 2 * i + 1;
      strips.push_back({a, c, e});
      strips.push_back({a, e, b});
    }
  }
  out.clear();
  PDS::sample_polygon_soup(folds, strips, std::back_inserter(out),
                           PDS::parameters::number_of_points(1000).maximum_number_of_points(1000));
  EXPECT_NEAR(double(out.size()), 1000., 10.);
}

// Long thin faces are cut into rows about D long as darts reach them (Triangle_fragment_traits_3,
// "Long thin triangles"): the pieces the sampler holds follow the points more than the faces' length
// over D. A disk of 2000 slivers around its centre, 1 long and 0.003 wide, at D = 0.01: about 22,000
// points, and 64 rows a face. When all rows were made at the start, this was refused under a bound of
// 50,000 points (252,000 pieces beyond one a face), and under a larger bound 11.5 pieces a point were
// active at the peak, all of them at the start; 5.9 since the rows are made as darts reach them.
TEST(BadInput, ThinFacesAreSampledWithinTheBound)
{
  std::vector<Point> p{Point(0, 0, 0)};
  std::vector<std::array<std::size_t, 3>> t;
  const std::size_t n = 2000;
  for(std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * double(i) / double(n);
    p.push_back(Point(std::cos(a), std::sin(a), 0));
    t.push_back({0, 1 + i, 1 + (i + 1) % n});
  }
  for(int count_mode = 0; count_mode < 2; ++count_mode) {
    std::vector<Point> out;
    PDS::Sampling_statistics stats;
    if(count_mode)
      PDS::sample_polygon_soup(p, t, std::back_inserter(out),
                               PDS::parameters::number_of_points(22000).maximum_number_of_points(50000).statistics(
                                   std::ref(stats)));
    else
      PDS::sample_polygon_soup(p, t, std::back_inserter(out),
                               PDS::parameters::minimum_distance(0.01).maximum_number_of_points(50000).statistics(
                                   std::ref(stats)));
    EXPECT_GT(out.size(), 15000u);
    EXPECT_LT(out.size(), 30000u);
    EXPECT_LT(double(stats.peak_active_fragments), 8 * double(out.size())) << "count mode " << count_mode;
    EXPECT_TRUE(PDS::is_poisson_disk_set(out, stats.minimum_distance));
  }
}

// A count whose bound is not reached works even where area / (pi r^2) at the distance tried would
// exceed the bound; the largest bounds convert without overflow; a count is a whole number.
TEST(BadInput, CountsAndBoundsAtTheirExtremes)
{
  const Mesh m = triangle();
  std::vector<Point> out;
  // the distance tried for 600 points has area / (pi r^2) near 1,100
  PDS::sample_triangle_mesh(m, std::back_inserter(out),
                            PDS::parameters::number_of_points(600).maximum_number_of_points(1000));
  EXPECT_NEAR(double(out.size()), 600., 6.);
  EXPECT_THROW(sample(m, PDS::parameters::number_of_points(1001).maximum_number_of_points(1000)),
               PDS::Point_limit_exceeded);
  // a target at the bound: the runs of the search that overshoot it stop at the bound (before, the
  // first one ended the search with Point_limit_exceeded), and a larger distance reaches it from below
  out.clear();
  PDS::Sampling_statistics stats;
  PDS::sample_triangle_mesh(
      m, std::back_inserter(out),
      PDS::parameters::number_of_points(1000).maximum_number_of_points(1000).statistics(std::ref(stats)));
  EXPECT_LE(out.size(), 1000u);
  EXPECT_GE(out.size(), 990u);
  EXPECT_GT(stats.number_of_runs, 1u);
  expect_maximal_poisson_disk_set(m, out, stats.minimum_distance);
  out.clear();
  const std::size_t largest = std::numeric_limits<std::size_t>::max();
  PDS::sample_triangle_mesh(m, std::back_inserter(out), PDS::parameters::radius(0.05).maximum_number_of_points(largest));
  EXPECT_GT(out.size(), 10u);
  EXPECT_THROW(sample(m, PDS::parameters::number_of_points(largest)), PDS::Point_limit_exceeded);
  // a count above the largest size_t is named as given (it read 18446744073709551615)
  const std::string huge =
      what_thrown<PDS::Point_limit_exceeded>([&] { sample(m, PDS::parameters::number_of_points(1e300)); });
  EXPECT_NE(huge.find("number_of_points (1e+300) exceeds maximum_number_of_points (100000000)"), std::string::npos)
      << huge;
  EXPECT_THROW(sample(m, PDS::parameters::number_of_points(2.5)), PDS::Invalid_input);
  EXPECT_THROW(sample(m, PDS::parameters::radius(0.05).maximum_number_of_points(1.5)), PDS::Invalid_input);
}

// Squares of distances below the smallest normal double lose their relative precision: the
// distances are bounded, and within the bounds, triangles far from unit size sample as at unit size.
TEST(BadInput, DistancesOutsideTheHandledRange)
{
  for(int e : {-420, 420}) {
    const double s = std::ldexp(1., e);
    Mesh m;
    m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(s, 0, 0)), m.add_vertex(Point(0, s, 0)));
    EXPECT_THROW(sample(m, PDS::parameters::minimum_distance(0.1 * s)), PDS::Invalid_input) << e;
    // the distance the count needs is named as such, not as a distance given (nor, where the first
    // estimate underflowed to 0, as a distance that is not positive); below the range, the search
    // first tries its lower end, 2^-400, where the triangle, 2^-420 wide, gets one point
    for(std::size_t n : {std::size_t(50), std::size_t(1)}) {
      if(e < 0 && n == 1) {
        std::vector<Point> one;
        PDS::Sampling_statistics stats;
        PDS::sample_triangle_mesh(m, std::back_inserter(one),
                                  PDS::parameters::number_of_points(1).statistics(std::ref(stats)));
        EXPECT_EQ(one.size(), 1u);
        EXPECT_EQ(stats.minimum_distance, std::ldexp(1., -400));
        continue;
      }
      const std::string what =
          what_thrown<PDS::Invalid_input>([&] { sample(m, PDS::parameters::number_of_points(n)); });
      const std::string named = e < 0 ? "the search for 50 points needs a minimum distance of about"
                                      : "about " + std::to_string(n) + " points on a surface of area";
      EXPECT_NE(what.find(named), std::string::npos) << e << ": " << what;
      EXPECT_NE(what.find("scale the input"), std::string::npos) << e << ": " << what;
    }
    EXPECT_THROW(PDS::is_maximal(m, std::vector<Point>{Point(0, 0, 0)}, 0.1 * s), PDS::Invalid_input) << e;
    std::vector<Point> out;
    EXPECT_THROW(PDS::sample_sphere(K::Sphere_3(Point(0, 0, 0), s * s), std::back_inserter(out),
                                    PDS::parameters::minimum_distance(0.3 * s)),
                 PDS::Invalid_input)
        << e;
  }
  // A later distance of the search below the precision is named as the search's too: two copies of a
  // triangle at 10^8 from the origin, where 75 points need 0.096, just above the limit (0.093), and
  // give about half as many (the engine called the next distance "the minimum distance")
  {
    const std::vector<Point> p = {Point(1e8, 0, 0), Point(1e8 + 1, 0, 0), Point(1e8, 1, 0)};
    const std::vector<std::array<std::size_t, 3>> t = {{0, 1, 2}, {0, 1, 2}};
    std::vector<Point> out;
    const std::string what = what_thrown<PDS::Invalid_input>([&] {
      PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::number_of_points(75));
    });
    EXPECT_NE(what.find("the search for 75 points needs a minimum distance of about"), std::string::npos) << what;
    EXPECT_NE(what.find("too small for the precision"), std::string::npos) << what;
  }
  // a count that the smallest distance the precision allows gives is reached, though the first
  // estimate is below it: one point on a triangle 10^-3 wide at 10^6 from the origin, where 0.00059
  // is below the limit, 0.00093 (it was refused); not 50, which need a distance below the limit
  {
    const std::vector<Point> p = {Point(1e6, 1e6, 1e6), Point(1e6 + 1e-3, 1e6, 1e6), Point(1e6, 1e6 + 1e-3, 1e6)};
    const std::vector<std::array<std::size_t, 3>> t = {{0, 1, 2}};
    for(std::size_t n : {1, 2}) {
      std::vector<Point> out;
      PDS::Sampling_statistics stats;
      PDS::sample_polygon_soup(p, t, std::back_inserter(out),
                               PDS::parameters::number_of_points(n).statistics(std::ref(stats)));
      EXPECT_NEAR(double(out.size()), double(n), 1.) << n; // within one point
      EXPECT_GE(stats.minimum_distance, 0.00093) << n;
      EXPECT_TRUE(PDS::is_maximal_on_polygon_soup(p, t, out, stats.minimum_distance)) << n;
    }
    std::vector<Point> out;
    const std::string what = what_thrown<PDS::Invalid_input>([&] {
      PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::number_of_points(50));
    });
    EXPECT_NE(what.find("too small for the precision"), std::string::npos) << what;
  }
  // a triangle whose area is about the smallest double: the first estimate no longer underflows to 0
  {
    Mesh m;
    m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(1e-200, 0, 0)), m.add_vertex(Point(0, 1e-200, 0)));
    const std::string what =
        what_thrown<PDS::Invalid_input>([&] { sample(m, PDS::parameters::number_of_points(10000)); });
    EXPECT_NE(what.find("scale the input"), std::string::npos) << what;
    EXPECT_EQ(what.find("about 0,"), std::string::npos) << what;
  }
  // the area of a triangle is the length of a cross product, whose square underflows (2^-1200) or
  // overflows (2^1200) here
  for(int e : {-300, 300}) {
    const double s = std::ldexp(1., e);
    Mesh m;
    m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(s, 0, 0)), m.add_vertex(Point(0, s, 0)));
    std::vector<Point> out;
    PDS::sample_triangle_mesh(m, std::back_inserter(out), PDS::parameters::minimum_distance(0.1 * s));
    EXPECT_GT(out.size(), 10u) << e;
    EXPECT_TRUE(PDS::is_poisson_disk_set(out, 0.1 * s)) << e;
    EXPECT_TRUE(PDS::is_maximal(m, out, 0.1 * s)) << e;
  }
}

// An area above the largest double, of one triangle or of their sum, is refused by name in either
// size mode: the message said the surface had no part of positive, finite area.
TEST(BadInput, AreasAboveTheDoubles)
{
  std::vector<Point> p = {Point(10, 0, 0), Point(11, 0, 0), Point(10, 1, 0),
                          Point(0, 0, 0),  Point(1e160, 0, 0), Point(0, 1e160, 0)};
  std::vector<std::array<std::size_t, 3>> t = {{0, 1, 2}, {3, 4, 5}};
  std::vector<Point> out;
  for(int mode = 0; mode < 2; ++mode) {
    const std::string what = what_thrown<PDS::Invalid_input>([&] {
      if(mode == 0) PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::minimum_distance(1e150));
      else PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::number_of_points(50));
    });
    EXPECT_NE(what.find("polygon 1 has an area above the largest double"), std::string::npos) << mode << ": " << what;
  }
  // triangles of finite areas whose sum is not
  p = {Point(0, 0, 0), Point(1e154, 0, 0), Point(0, 3e154, 0), Point(0, 0, 1e154)};
  t = {{0, 1, 2}, {0, 2, 3}};
  const std::string what = what_thrown<PDS::Invalid_input>(
      [&] { PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::number_of_points(50)); });
  EXPECT_NE(what.find("the surface's area overflows a double"), std::string::npos) << what;
}

TEST(BadInput, RadiusBelowCoordinatePrecision)
{
  Mesh m;
  m.add_face(m.add_vertex(Point(1e9, 0, 0)), m.add_vertex(Point(1e9 + 1, 0, 0)), m.add_vertex(Point(1e9, 1, 0)));
  EXPECT_THROW(sample(m, PDS::parameters::radius(1e-4).maximum_number_of_points(1000000000)), PDS::Invalid_input);
  // the certificate refuses it too (it would split every piece to its floor, about 2^30 pieces, since
  // no ball can be proven to cover one); the sample is within 2^44 d of the origin, so that the grid
  // of the samples would take it
  EXPECT_THROW(PDS::is_maximal(m, std::vector<Point>{Point(1e9, 0, 0)}, 2e-4), PDS::Invalid_input);
  // the message gives the numbers readably, not as 0.000000
  const std::string what = what_thrown<PDS::Invalid_input>(
      [&] { sample(m, PDS::parameters::radius(1e-7).maximum_number_of_points(1000000000)); });
  EXPECT_NE(what.find("2e-07"), std::string::npos) << what;
}

// A face of zero area is neither sampled nor certified: far from the others, it does not limit the
// distance to the precision of its coordinates (a unit triangle with such a face at 10^9 was refused
// at d = 0.01).
TEST(BadInput, FacesOfZeroAreaDoNotLimitTheDistance)
{
  Mesh m;
  m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(1, 0, 0)), m.add_vertex(Point(0, 1, 0)));
  m.add_face(m.add_vertex(Point(1e9, 0, 0)), m.add_vertex(Point(2e9, 0, 0)), m.add_vertex(Point(3e9, 0, 0)));
  std::vector<Point> points;
  ASSERT_NO_THROW(PDS::sample_triangle_mesh(m, std::back_inserter(points), PDS::parameters::minimum_distance(0.01)));
  EXPECT_GT(points.size(), 3000u);
  EXPECT_TRUE(PDS::is_poisson_disk_set(points, 0.01));
  EXPECT_TRUE(PDS::is_maximal(m, points, 0.01));
  // a face of positive area there still does
  Mesh far = m;
  far.add_face(far.add_vertex(Point(1e9, 0, 0)), far.add_vertex(Point(1e9 + 1, 0, 0)),
               far.add_vertex(Point(1e9, 1, 0)));
  EXPECT_THROW(sample(far, PDS::parameters::minimum_distance(0.01)), PDS::Invalid_input);
}

// A Surface_mesh whose removed faces were not collected: the messages name the bad face by its index
// too, not only by its place among the faces left (they said "face 1" for the face f2).
TEST(BadInput, MessagesNameTheFaceAsTheMeshDoes)
{
  // a quadrilateral, a corner not finite, an area above the largest double
  for(const std::string kind : {"not a triangle", "not finite", "above the largest double"}) {
    Mesh m;
    const bool quad = kind == "not a triangle", huge = kind == "above the largest double";
    const double y = kind == "not finite" ? nan : huge ? 1e300 : 1;
    const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0)), c = m.add_vertex(Point(0, 1, 0));
    const auto d = m.add_vertex(Point(5, 0, 0)), e = m.add_vertex(Point(6, 0, 0)), f = m.add_vertex(Point(5, 1, 0));
    const auto g = m.add_vertex(Point(9, 0, 0)), h = m.add_vertex(Point(huge ? 1e300 : 10, 0, 0));
    const auto i = m.add_vertex(Point(10, 1, 0)), j = m.add_vertex(Point(9, y, 0));
    m.add_face(a, b, c);
    m.add_face(d, e, f);
    if(quad) m.add_face(g, h, i, j);
    else m.add_face(g, h, j);
    CGAL::Euler::remove_face(halfedge(*m.faces().begin(), m), m);
    ASSERT_EQ(m.number_of_faces(), 2u);
    ASSERT_TRUE(m.has_garbage());
    const std::string what = what_thrown<PDS::Invalid_input>([&] { sample(m, PDS::parameters::radius(0.1)); });
    EXPECT_NE(what.find("face 1 in the order of faces(tm) (f2)"), std::string::npos) << what;
    EXPECT_NE(what.find(kind), std::string::npos) << what;
  }
}

TEST(BadInput, NonTriangleFaces)
{
  const Mesh m = load_mesh("cube_poly.off"); // quadrilaterals from CGAL's data set
  const std::string what = what_thrown<PDS::Invalid_input>([&] { sample(m, PDS::parameters::radius(0.1)); });
  EXPECT_NE(what.find("not a triangle"), std::string::npos) << what;
  const std::vector<Point> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<Point> out;
  EXPECT_THROW(PDS::sample_polygon_soup(p, std::vector<std::vector<int>>{{0, 1, 2, 3}}, std::back_inserter(out),
                                        PDS::parameters::radius(0.1)),
               PDS::Invalid_input);
  EXPECT_THROW(PDS::sample_polygon_soup(p, std::vector<std::vector<int>>{{0, 1, 7}}, std::back_inserter(out),
                                        PDS::parameters::radius(0.1)),
               PDS::Invalid_input)
      << "index out of range";
  EXPECT_THROW(PDS::sample_polygon_soup(p, std::vector<std::vector<int>>{}, std::back_inserter(out),
                                        PDS::parameters::radius(0.1)),
               PDS::Invalid_input)
      << "no polygons";
}

// (a negative or NaN squared radius is already refused by CGAL::Sphere_3's own precondition)
TEST(BadInput, BadSpheres)
{
  std::vector<Point> out;
  for(double sq : {0., inf})
    EXPECT_THROW(PDS::sample_sphere(K::Sphere_3(CGAL::ORIGIN, sq), std::back_inserter(out), PDS::parameters::radius(0.1)),
                 PDS::Invalid_input);
  // a sphere of radius 1e160 has a squared radius that overflows, one of 1e-170 one that underflows:
  // the message names the squared radius, since the radius itself is finite and positive
  for(double r : {1e160, 1e-170}) {
    const std::string what = what_thrown<PDS::Invalid_input>([&] {
      PDS::sample_sphere(K::Sphere_3(CGAL::ORIGIN, r * r), std::back_inserter(out),
                         PDS::parameters::number_of_points(10));
    });
    EXPECT_NE(what.find("the sphere's squared radius"), std::string::npos) << r << ": " << what;
  }
}

// A negative index in a soup is named as it is, not as the size_t it converts to.
TEST(BadInput, NegativeIndexInASoup)
{
  const std::vector<Point> p = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  const std::vector<std::array<int, 3>> t = {{0, 1, 2}, {0, -1, 2}};
  std::vector<Point> out;
  EXPECT_EQ(what_thrown<PDS::Invalid_input>([&] {
              PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::radius(0.1));
            }),
            "Poisson_disk_sampling_3: polygon 1 refers to point -1 of 3");
}

TEST(BadInput, UnreachableCount)
{
  // 200 tiny triangles on a line, 1000 apart: the count depends on the distance only through how
  // many neighbours a sample's ball reaches, and jumps from about 58 (distances from 2000 to 3000)
  // to about 40 (from 3000 to 4000): 50 is out of reach
  std::vector<Point> p;
  std::vector<std::array<std::size_t, 3>> t;
  for(std::size_t i = 0; i < 200; ++i) {
    const double x = 1000. * double(i);
    p.insert(p.end(), {Point(x, 0, 0), Point(x + 1e-3, 0, 0), Point(x, 1e-3, 0)});
    t.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  std::vector<Point> out;
  const std::string what = what_thrown<PDS::Target_not_reached>(
      [&] { PDS::sample_polygon_soup(p, t, std::back_inserter(out), PDS::parameters::number_of_points(50)); });
  // the tolerance is written as a number, not as 1.000000
  EXPECT_NE(what.find("no minimum distance gave 50 points within 1 (1% of them, at least one); the closest had "),
            std::string::npos)
      << what;
}

} // namespace
