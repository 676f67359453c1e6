// The bundle reader on hostile input (issue 18, fuzz/): a bundle is data from elsewhere, so the
// files it names must stay inside it and be regular files; each case once read outside the
// bundle or blocked on a device or FIFO. Inputs also in fuzz/corpus/bundle/.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "gap/bundle.h"
#include "tests/gap/bundle_fixture.h"

namespace tribo::gap {
namespace {

class BundleHostile : public BundleFixture {
 protected:
  BundleHostile() : BundleFixture("tribo_gap_bundle_hostile_") {}
  void SetUp() override {
    BundleFixture::SetUp();
    write("traces/a.csv", "t_s,mu\n0,0.1\n1,0.2\n2,0.3\n");
  }
  void runs(const std::string& file) { write("runs.csv", "run_id,v_m_per_s,file\n0,1e-3," + file + "\n"); }
};

TEST_F(BundleHostile, TraceInsideTheBundleIsRead) {
  runs("traces/./a.csv");
  EXPECT_EQ(error(), "");
}

TEST_F(BundleHostile, TracePathsOutsideTheBundleAreRefused) {
  // "/dev/zero" was opened and read line by line: one endless line, memory until killed.
  for (const std::string file : {"/dev/zero", "/etc/hostname", "../a.csv", "traces/../../a.csv"}) {
    runs(file);
    const std::string e = error();
    EXPECT_NE(e.find("runs.csv:2: trace file '" + file + "' must be a path inside the bundle"), std::string::npos) << e;
  }
}

TEST_F(BundleHostile, TraceThatIsAFolderIsRefused) {
  runs("traces");
  EXPECT_NE(error().find("is not a regular file"), std::string::npos) << error();
}

TEST_F(BundleHostile, DataFileThatIsAFifoIsRefusedWithoutBlocking) {
  // Opening a FIFO for reading blocks until a writer comes: the reader used to wait forever.
  ASSERT_EQ(mkfifo((dir_ / "static_friction.csv").c_str(), 0600), 0);
  EXPECT_NE(error().find("static_friction.csv: not a regular file"), std::string::npos) << error();
}

}  // namespace
}  // namespace tribo::gap
