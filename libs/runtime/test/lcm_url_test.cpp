#include "vsl/runtime/lcm_url.hpp"

#include <gtest/gtest.h>

#include "vsl/runtime/config.hpp"

namespace vsl::runtime {
namespace {

TEST(runtime_lcm_url, TheUrlsVslShipsAreFine) {
  for (const char* url :
       {kDefaultLcmUrl, "udpm://239.255.76.67:7667?ttl=0", "udpm://", "memq://",
        "file:///tmp/session.lcmlog?speed=1.5&mode=r", "file://log.lcmlog?start_timestamp=-4",
        "tcpq://localhost:7700",
        "udpm://239.255.76.67:7701?ttl=0&recv_buf_size=4194304&transmit_only=false"}) {
    EXPECT_EQ(lcm_url_problem(url), "") << url;
  }
}

TEST(runtime_lcm_url, AMalformedUrlSaysWhatIsWrong) {
  EXPECT_EQ(lcm_url_problem("localhost:7667"), "expected provider://network?options");
  EXPECT_EQ(lcm_url_problem("udp://239.255.76.67:7667"),
            "unknown provider 'udp' (liblcm has udpm, mpudpm, memq, file, tcpq)");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:99999"), "expected a port 1-65535, got '99999'");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67"), "expected ADDRESS:PORT, got '239.255.76.67'");
  EXPECT_EQ(lcm_url_problem("udpm://192.168.1.2:7667"),
            "expected an IPv4 multicast address (224.0.0.0 to 239.255.255.255), got "
            "'192.168.1.2'");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76:7667"),
            "expected an IPv4 multicast address (224.0.0.0 to 239.255.255.255), got '239.255.76'");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:7667?ttl=300"), "option ttl=300: expected 0-255");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:7667?recv_buf_size=big"),
            "option recv_buf_size=big: expected a size in bytes");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:7667?tll=0"), "unknown option 'tll' for udpm://");
  EXPECT_EQ(lcm_url_problem("udpm://239.255.76.67:7667?ttl"), "option 'ttl' needs a value");
  EXPECT_EQ(lcm_url_problem("file://"), "file:// needs a path");
  EXPECT_EQ(lcm_url_problem("file://x.log?speed=-1"),
            "option speed=-1: expected a non-negative number");
  EXPECT_EQ(lcm_url_problem("tcpq://localhost"), "expected HOST:PORT, got 'localhost'");
}

}  // namespace
}  // namespace vsl::runtime
