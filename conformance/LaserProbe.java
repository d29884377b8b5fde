import org.jaria.range.LaserScan;
import org.jaria.connection.ArTcpConnection;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.robot.ArRobot;

/**
 * A hand-run probe: JAria's ArRobot with its ArSimulatedLaser against any simulator (JAria's, or
 * AMRISim/MobileSim). Run as a single-file program:
 *
 * <pre>
 * java -cp 'tools/target/jaria-tools.jar:tools/target/lib/*' conformance/LaserProbe.java HOST PORT
 * </pre>
 *
 * Prints how long the first complete sweep took, then after three seconds the sweeps, readings per
 * sweep, packets dropped as malformed and the closest reading ahead.
 */
public class LaserProbe {
  public static void main(String[] a) throws Exception {
    ArRobot robot = new ArRobot();
    robot.setDeviceConnection(new ArTcpConnection(a[0], Integer.parseInt(a[1])));
    ArSimulatedLaser laser = new ArSimulatedLaser();
    robot.addRangeDevice(laser);
    if (!robot.blockingConnect()) {
      System.out.println("could not connect to " + a[0] + ":" + a[1]);
      System.exit(1);
    }
    robot.runAsync(true);
    long t0 = System.nanoTime();
    while (laser.getSweepCount() == 0 && System.nanoTime() - t0 < 10_000_000_000L) {
      Thread.sleep(20);
    }
    System.out.printf("first sweep after %.2f s%n", (System.nanoTime() - t0) / 1e9);
    Thread.sleep(3000);
    LaserScan scan = laser.getLaserScan();
    System.out.printf(
        "sweeps %d, readings per sweep %d, dropped %d, closest ahead %.0f mm%n",
        laser.getSweepCount(),
        scan == null ? 0 : scan.size(),
        robot.getDropCounters().total(),
        laser.currentReadingPolar(-10, 10));
    robot.stopRunning();
    robot.disconnect();
    System.exit(0);
  }
}
