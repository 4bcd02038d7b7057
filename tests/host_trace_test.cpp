// Fragment traces: a rendered frame's records survive the round trip bit for bit, the write
// is atomic, and every malformed file names its line and column.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "formats/formats.hpp"
#include "geometry/mesh.hpp"
#include "raster/rasterizer.hpp"
#include "trace/fragment_trace.hpp"

namespace tmu::host {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("tmu_host_trace_" + std::to_string(::getpid()) + "_" + info->name());
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

FragmentTrace rendered_trace() {
  Scene scene;
  scene.path = "scenes/test.json";
  scene.camera.position = {1, 2, 4};
  scene.camera.width = 40;
  scene.camera.height = 30;
  scene.lights = {{Light::Kind::kDirectional, {-1, -2, -1}, {1, 1, 1}}};
  scene.materials.resize(2);
  Object sphere;
  sphere.shape = Object::Shape::kSphere;
  sphere.material = 1;
  scene.objects.push_back(sphere);
  const std::vector<Fragment> frags = rasterize(scene, {make_mesh(sphere)}, {{64, 64}, {128, 256}});
  FragmentTrace t;
  t.scene = scene.path;
  t.width = scene.camera.width;
  t.height = scene.camera.height;
  for (const Fragment& f : frags) t.records.push_back(quantize(f));
  return t;
}

TEST(HostTraceTest, RoundTripKeepsEveryRecord) {
  const TempDir dir;
  FragmentTrace t = rendered_trace();
  ASSERT_GT(t.records.size(), 100u);
  // The extremes of every field, too.
  FragmentRecord lo, hi;
  lo.u = lo.v = lo.r1[0] = lo.r2[1] = static_cast<int32_t>(formats::kTexCoord.min_raw());
  lo.lambda = static_cast<int32_t>(formats::kLod.min_raw());
  lo.solid[0] = static_cast<int32_t>(formats::kSolidCoord.min_raw());
  lo.normal[1] = lo.view[2] = static_cast<int16_t>(formats::kUnitComp.min_raw());
  hi.x = 39;
  hi.y = 29;
  hi.material = 255;
  hi.u = hi.v = hi.r1[1] = hi.r2[0] = static_cast<int32_t>(formats::kTexCoord.max_raw());
  hi.lambda = static_cast<int32_t>(formats::kLod.max_raw());
  hi.shade = 0xFFFFFFFFu;
  hi.solid[2] = static_cast<int32_t>(formats::kSolidCoord.max_raw());
  hi.normal[0] = hi.view[1] = static_cast<int16_t>(formats::kUnitComp.max_raw());
  t.records.push_back(lo);
  t.records.push_back(hi);
  write_trace(dir / "t.csv", t);
  const FragmentTrace back = read_trace(dir / "t.csv");
  EXPECT_EQ(back.scene, t.scene);
  EXPECT_EQ(back.width, 40);
  EXPECT_EQ(back.height, 30);
  ASSERT_EQ(back.records.size(), t.records.size());
  for (size_t i = 0; i < t.records.size(); ++i) ASSERT_EQ(back.records[i], t.records[i]) << i;
  // Atomic: only the file itself is left in the folder.
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir.path())) files += e.is_regular_file();
  EXPECT_EQ(files, 1u);
}

TEST(HostTraceTest, FileFormatIsTheDocumentedCsv) {
  const TempDir dir;
  FragmentTrace t;
  t.scene = "a.json";
  t.width = 8;
  t.height = 4;
  FragmentRecord r;
  r.x = 3;
  r.y = 2;
  r.material = 1;
  r.u = -5;
  r.v = 300;
  r.lambda = -256;
  r.shade = 0x80FF00FFu;
  r.normal[2] = 16384;
  t.records = {r};
  write_trace(dir / "t.csv", t);
  std::ifstream in(dir / "t.csv");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("# scene: a.json\n# frame: 8x4\n"
                            "x,y,material,u,v,lambda,shade,r1u,r1v,r2u,r2v,su,sv,sw,nx,ny,nz,vx,vy,"
                            "vz\n3,2,1,-5,300,-256,0x80FF00FF,0,0,0,0,0,0,0,0,0,16384,0,0,0\n"),
            std::string::npos)
      << text.str();
}

// Writes `text` and expects read_trace to fail at `field` with `reason` in the message.
void expect_error(const std::string& text, const std::string& field, const std::string& reason) {
  const TempDir dir;
  const std::string path = dir / "bad.csv";
  std::ofstream(path) << text;
  try {
    read_trace(path);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

const std::string kPreamble =
    "# scene: s.json\n# frame: 8x4\n"
    "x,y,material,u,v,lambda,shade,r1u,r1v,r2u,r2v,su,sv,sw,nx,ny,nz,vx,vy,vz\n";
const std::string kGood = "1,2,0,10,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,16384,0,0,16384\n";

TEST(HostTraceTest, MalformedFilesNameLineAndColumn) {
  // The good file reads.
  {
    const TempDir dir;
    std::ofstream(dir / "ok.csv") << kPreamble << kGood << "\n" << kGood;
    EXPECT_EQ(read_trace(dir / "ok.csv").records.size(), 2u);
  }
  expect_error("# frame: 8x4\nx,y,material\n", "line 2", "expected the header");
  expect_error("x,y,material,u,v,lambda,shade,r1u,r1v,r2u,r2v,su,sv,sw,nx,ny,nz,vx,vy,vz\n",
               "line 1", "missing the '# frame: WxH' comment");
  expect_error("# frame: 8 by 4\n", "line 1", "bad frame comment");
  expect_error("# frame: 0x4\n", "line 1", "bad frame comment");
  expect_error("# just a comment\n", "", "no header line");
  expect_error(kPreamble + kGood + "1,2,3\n", "line 5", "expected 20 columns, got 3");
  expect_error(kPreamble + "1,2,0,10,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,16384,0,0,16384,7\n",
               "line 4", "expected 20 columns, got 21");
  expect_error(kPreamble + "1,2,256,10,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 3 (material)", "256 is outside UQ8.0 (0..255)");
  expect_error(kPreamble + "1,2,0,8388608,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 4 (u)", "outside SQ16.8");
  expect_error(kPreamble + "1,2,0,10,20,-8193,0x000000FF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 6 (lambda)", "outside SQ6.8");
  expect_error(kPreamble + "1,2,0,10,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,32768,0,0,0\n",
               "line 4, column 17 (nz)", "outside SQ2.14");
  expect_error(kPreamble + "1,2,0,10,20,0,255,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 7 (shade)", "expected 0xRRGGBBAA");
  expect_error(kPreamble + "1,2,0,10,20,0,0x1FFFFFFFF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 7 (shade)", "outside UQ32.0");
  expect_error(kPreamble + "1,2,0,1.5,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 4 (u)", "expected an integer, got '1.5'");
  expect_error(kPreamble + "1,2,0,,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 4 (u)", "expected an integer, got ''");
  expect_error(kPreamble + "8,2,0,10,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 1 (x)", "outside the 8x4 frame");
  expect_error(kPreamble + "1,4,0,10,20,0,0x000000FF,0,0,0,0,0,0,0,0,0,0,0,0,0\n",
               "line 4, column 2 (y)", "outside the 8x4 frame");
}

TEST(HostTraceTest, MissingFileIsAnInputError) {
  EXPECT_THROW(read_trace("/nonexistent/trace.csv"), InputError);
  FragmentTrace t;
  EXPECT_THROW(write_trace("/nonexistent/dir/trace.csv", t), InputError);
}

}  // namespace
}  // namespace tmu::host
