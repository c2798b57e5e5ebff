// Runs lcm-spy itself (lcm.spy.Spy, the window tools/vsl-spy opens) on a recorded session (LCM
// Java's file:// provider plays the log into it, big stereo frames included, which lcm-spy's
// UDP socket would only receive with net.core.rmem_default raised), and then reads lcm-spy's own
// channel table: for every channel, the class lcm-spy decoded it with (found by fingerprint in
// its type database), the messages received, the decode errors and the last decoded message. In
// package lcm.spy to read that table (package-private), so it is compiled onto the class path,
// not run as source.
//
//   java -cp DIR:$(tools/vsl-spy --classpath) lcm.spy.SpyDecodeCheck LOG
// Prints "ok: CHANNEL TYPE N" per decoded channel, "FAIL: ..." otherwise; exit 1 on any failure
// or when no channel was received.
package lcm.spy;

import java.util.ArrayList;

public class SpyDecodeCheck {
  public static void main(String[] args) throws Exception {
    Spy spy = new Spy("file://" + args[0] + "?speed=4");
    // The log is played in a thread of its own: done when the counts stop changing.
    long last = -1;
    for (int i = 0; i < 120; ++i) {
      Thread.sleep(1000);
      long total = 0;
      synchronized (spy) {
        for (ChannelData cd : spy.channelList) total += cd.nreceived;
      }
      if (total > 0 && total == last) break;
      last = total;
    }
    int failures = 0;
    ArrayList<ChannelData> channels;
    synchronized (spy) {
      channels = new ArrayList<>(spy.channelList);
    }
    for (ChannelData cd : channels) {
      // liblcm's own start-up probe of the multicast loopback: raw bytes, no LCM type.
      if (cd.name.equals("LCM_SELF_TEST")) continue;
      if (cd.cls == null || cd.nerrors > 0 || cd.last == null) {
        System.out.printf("FAIL: %s: lcm-spy has %s, %d received, %d decode errors%n", cd.name,
            cd.cls == null ? "no type for its fingerprint" : cd.cls.getName(), cd.nreceived,
            cd.nerrors);
        ++failures;
      } else {
        System.out.printf("ok: %s %s %d%n", cd.name, cd.cls.getName(), cd.nreceived);
      }
    }
    if (channels.isEmpty()) {
      System.out.println("FAIL: lcm-spy received nothing");
      ++failures;
    }
    System.exit(failures == 0 ? 0 : 1);
  }
}
