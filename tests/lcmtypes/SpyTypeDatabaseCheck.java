// Asks lcm-spy's own type database (lcm.spy.LCMTypeDatabase: lcm.spy.Spy builds one at start-up by
// scanning the class path, and decodes each received message with the class it finds for the
// message's fingerprint) for every vsl type named on the command line.
//
// Run with the class path of tools/vsl-spy (Java 11+ source launcher):
//   java -cp "$(tools/vsl-spy --classpath)" tests/lcmtypes/SpyTypeDatabaseCheck.java image_t ...
// Prints lcm-spy's "Found N LCM types" line, then one line per type; exit code 1 if any type is
// not found.

import lcm.spy.LCMTypeDatabase;

public class SpyTypeDatabaseCheck {
  public static void main(String[] args) throws Exception {
    LCMTypeDatabase db = new LCMTypeDatabase();
    int failures = 0;
    for (String name : args) {
      String className = "vsl." + name;
      Class<?> cls;
      try {
        cls = Class.forName(className);
      } catch (ClassNotFoundException e) {
        System.out.println("FAIL: " + className + " is not on the class path");
        ++failures;
        continue;
      }
      long fingerprint = cls.getField("LCM_FINGERPRINT").getLong(null);
      Class<?> found = db.getClassByFingerprint(fingerprint);
      if (found == null || !found.getName().equals(className)) {
        System.out.printf("FAIL: lcm-spy does not decode fingerprint 0x%016x (%s), it has %s%n",
            fingerprint, className, found == null ? "nothing" : found.getName());
        ++failures;
      } else {
        System.out.printf(
            "ok: lcm-spy decodes fingerprint 0x%016x as %s%n", fingerprint, found.getName());
      }
    }
    System.exit(failures == 0 ? 0 : 1);
  }
}
