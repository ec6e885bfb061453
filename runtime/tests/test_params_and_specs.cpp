// Parameter access, name suggestions and the duration histogram.
#include <gmock/gmock.h>

#include <Eigen/Core>
#include <random>

#include "kestrel/param_spec.hpp"
#include "kestrel/params.hpp"
#include "kestrel/runtime/diagnostics.hpp"
#include "kestrel/runtime/histogram.hpp"

using namespace kestrel;

TEST(Params, TypedAccessWidensIntegersAndRefusesWrongTypes) {
  Params p;
  p.set("n", std::int64_t{300});
  p.set("x", 1.5);
  p.set("s", std::string("fifo"));
  EXPECT_EQ(p.get<int>("n"), 300);
  EXPECT_DOUBLE_EQ(p.get<double>("n"), 300.0);
  EXPECT_DOUBLE_EQ(p.get<double>("x"), 1.5);
  EXPECT_EQ(p.get<std::string>("s"), "fifo");
  EXPECT_THROW(p.get<int>("x"), Error);
  EXPECT_THROW(p.get<std::uint8_t>("n"), Error);  // does not fit
  EXPECT_THROW(p.get<double>("missing"), Error);
  p.set("position", std::vector<double>{1, 2, 3});
  p.set("pair", std::vector<double>{1, 2});
  EXPECT_TRUE(p.get<Eigen::Vector3d>("position").isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_THROW(p.get<Eigen::Vector3d>("pair"), Error);
}

TEST(Params, SpecBuilderRecordsEverything) {
  const ParamSpec s = param("leaf_size", 0.1).with_unit("m").range(0.001, 5.0).describe("voxel edge");
  EXPECT_EQ(s.type, ParamType::number);
  EXPECT_EQ(to_string(*s.default_value), "0.1");
  EXPECT_EQ(s.unit, "m");
  EXPECT_EQ(*s.min, 0.001);
  EXPECT_EQ(*s.max, 5.0);
  EXPECT_EQ(param("name", "x").type, ParamType::string);
  EXPECT_EQ(param("n", 3).type, ParamType::integer);
  EXPECT_EQ(param("on", true).type, ParamType::boolean);
  EXPECT_EQ(param("v", std::vector<double>{1, 2}).type, ParamType::number_list);
  EXPECT_FALSE(required_param<double>("r").default_value);
}

TEST(NearestName, FindsTyposButNotUnrelatedWords) {
  const std::vector<std::string> names = {"voxel_filter", "euclidean_clusterer", "stereo_depth"};
  EXPECT_EQ(nearest_name("voxel_filtr", names), "voxel_filter");
  EXPECT_EQ(nearest_name("Voxel_Filter", names), "voxel_filter");
  EXPECT_EQ(nearest_name("stereo_dept", names), "stereo_depth");
  EXPECT_EQ(nearest_name("camera", names), "");
}

TEST(DurationHistogram, QuantilesWithinBucketPrecision) {
  DurationHistogram h;
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<std::int64_t> d(1000, 1000000);
  std::vector<std::int64_t> samples;
  for (int i = 0; i < 100000; ++i) {
    samples.push_back(d(rng));
    h.record(samples.back());
  }
  std::sort(samples.begin(), samples.end());
  for (double q : {0.5, 0.9, 0.99}) {
    const auto exact = static_cast<double>(samples[static_cast<std::size_t>(q * samples.size()) - 1]);
    EXPECT_NEAR(static_cast<double>(h.quantile(q)), exact, exact * 0.02) << q;
  }
  EXPECT_EQ(h.max(), samples.back());
  EXPECT_EQ(h.count(), 100000u);
  DurationHistogram small;
  for (int v : {3, 3, 7}) small.record(v);
  EXPECT_EQ(small.quantile(0.5), 3);
  EXPECT_EQ(small.quantile(1.0), 7);
}
