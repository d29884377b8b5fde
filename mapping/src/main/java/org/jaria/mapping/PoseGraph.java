package org.jaria.mapping;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import org.ejml.data.DMatrixRMaj;
import org.ejml.data.DMatrixSparseCSC;
import org.ejml.data.DMatrixSparseTriplet;
import org.ejml.interfaces.linsol.LinearSolverSparse;
import org.ejml.ops.DConvertMatrixStruct;
import org.ejml.sparse.FillReducing;
import org.ejml.sparse.csc.factory.LinearSolverFactory_DSCC;

/**
 * The robot's poses along a drive and what scan matching measured between them: each edge says
 * "seen from pose i, pose j lies at (dx, dy, dth)", with a 3x3 information matrix saying how sure
 * that is. {@link #optimize} moves the poses so that all measurements agree as well as they can
 * (Gauss-Newton on the sum of squared, information-weighted errors), which is what spreads the
 * error a loop closure reveals over the whole loop.
 *
 * <p>Units inside are metres and radians, so position and angle errors have similar sizes; the
 * accessors take and give millimetres and degrees like the rest of ARIA. The first pose is held
 * fixed (the log's own frame). The normal equations are sparse (a pose touches only its neighbours
 * in the graph) and are solved with EJML's sparse Cholesky factorisation. Poses are numbered in the
 * order they are added, so the matrix is banded apart from the loop closures.
 *
 * <p>Not thread-safe.
 */
final class PoseGraph {

  private double[] x = new double[256];
  private double[] y = new double[256];
  private double[] th = new double[256];
  private int nodes;

  private int[] ei = new int[512];
  private int[] ej = new int[512];
  private double[] ez = new double[512 * 3];
  private double[] einfo = new double[512 * 6]; // xx xy xt yy yt tt
  private boolean[] eloop = new boolean[512];
  private int edges;

  /** Adds a pose (mm, degrees); returns its index. */
  int addNode(double xMm, double yMm, double thDeg) {
    if (nodes == x.length) {
      x = Arrays.copyOf(x, nodes * 2);
      y = Arrays.copyOf(y, nodes * 2);
      th = Arrays.copyOf(th, nodes * 2);
    }
    x[nodes] = xMm / 1000;
    y[nodes] = yMm / 1000;
    th[nodes] = Math.toRadians(thDeg);
    return nodes++;
  }

  int size() {
    return nodes;
  }

  int edgeCount() {
    return edges;
  }

  double xMm(int i) {
    return x[i] * 1000;
  }

  double yMm(int i) {
    return y[i] * 1000;
  }

  double thDeg(int i) {
    return Math.toDegrees(th[i]);
  }

  double thRad(int i) {
    return th[i];
  }

  /** Moves pose {@code i} (mm, degrees). */
  void set(int i, double xMm, double yMm, double thDeg) {
    x[i] = xMm / 1000;
    y[i] = yMm / 1000;
    th[i] = Math.toRadians(thDeg);
  }

  /**
   * Adds a measurement of pose {@code j} seen from pose {@code i}.
   *
   * @param dxMm where j lies ahead of i, mm
   * @param dyMm where j lies left of i, mm
   * @param dthDeg how much j is turned from i, degrees
   * @param info information in metres and radians: xx, xy, xt, yy, yt, tt
   * @param loop whether this is a loop closure (may be dropped if it disagrees with the rest)
   */
  void addEdge(int i, int j, double dxMm, double dyMm, double dthDeg, double[] info, boolean loop) {
    if (edges == ei.length) {
      int n = edges * 2;
      ei = Arrays.copyOf(ei, n);
      ej = Arrays.copyOf(ej, n);
      ez = Arrays.copyOf(ez, n * 3);
      einfo = Arrays.copyOf(einfo, n * 6);
      eloop = Arrays.copyOf(eloop, n);
    }
    ei[edges] = i;
    ej[edges] = j;
    ez[edges * 3] = dxMm / 1000;
    ez[edges * 3 + 1] = dyMm / 1000;
    ez[edges * 3 + 2] = Math.toRadians(dthDeg);
    System.arraycopy(info, 0, einfo, edges * 6, 6);
    eloop[edges] = loop;
    edges++;
  }

  /** The error of edge {@code k} at the current poses: x, y (m) and angle (rad). */
  void error(int k, double[] e) {
    int i = ei[k];
    int j = ej[k];
    double ci = Math.cos(th[i]);
    double si = Math.sin(th[i]);
    double dx = x[j] - x[i];
    double dy = y[j] - y[i];
    // pose j in frame i
    double lx = ci * dx + si * dy;
    double ly = -si * dx + ci * dy;
    double zt = ez[k * 3 + 2];
    double cz = Math.cos(zt);
    double sz = Math.sin(zt);
    double ux = lx - ez[k * 3];
    double uy = ly - ez[k * 3 + 1];
    e[0] = cz * ux + sz * uy;
    e[1] = -sz * ux + cz * uy;
    e[2] = wrap(th[j] - th[i] - zt);
  }

  /** The weighted squared error of edge {@code k}. */
  double chi2(int k) {
    double[] e = new double[3];
    error(k, e);
    double[] w = Arrays.copyOfRange(einfo, k * 6, k * 6 + 6);
    return e[0] * (w[0] * e[0] + w[1] * e[1] + w[2] * e[2])
        + e[1] * (w[1] * e[0] + w[3] * e[1] + w[4] * e[2])
        + e[2] * (w[2] * e[0] + w[4] * e[1] + w[5] * e[2]);
  }

  boolean isLoop(int k) {
    return eloop[k];
  }

  /**
   * Optimises, then drops the loop edge that disagrees most with the rest (weighted squared error
   * above {@code maxChi2}) and optimises again, until every loop edge agrees: one false recognition
   * must not bend the whole map, and dropping the worst one first keeps the true edges it had bent.
   *
   * @return how many loop edges were dropped
   */
  int optimizeDroppingOutliers(int iterations, double maxChi2) {
    int dropped = 0;
    optimize(iterations);
    for (int round = 0; round < 20; round++) {
      int worst = -1;
      double worstChi2 = maxChi2;
      for (int k = 0; k < edges; k++) {
        double c = eloop[k] ? chi2(k) : 0;
        if (c > worstChi2) {
          worstChi2 = c;
          worst = k;
        }
      }
      if (worst < 0) {
        break;
      }
      removeEdge(worst);
      dropped++;
      optimize(iterations);
    }
    return dropped;
  }

  private void removeEdge(int k) {
    int last = edges - 1;
    ei[k] = ei[last];
    ej[k] = ej[last];
    System.arraycopy(ez, last * 3, ez, k * 3, 3);
    System.arraycopy(einfo, last * 6, einfo, k * 6, 6);
    eloop[k] = eloop[last];
    edges--;
  }

  static double wrap(double a) {
    while (a > Math.PI) {
      a -= 2 * Math.PI;
    }
    while (a <= -Math.PI) {
      a += 2 * Math.PI;
    }
    return a;
  }

  /**
   * Gauss-Newton: at most {@code iterations} steps, stopping early once no pose moves more than a
   * tenth of a millimetre.
   *
   * @return the total weighted squared error after the last step
   */
  double optimize(int iterations) {
    if (nodes < 2 || edges == 0) {
      return 0;
    }
    int n = 3 * (nodes - 1); // pose 0 is fixed
    int[] order = EliminationOrder.reverseCuthillMcKee(nodes, ei, ej, edges);
    for (int it = 0; it < iterations; it++) {
      Map<Long, double[]> blocks = new HashMap<>();
      double[] b = new double[n];
      double[] e = new double[3];
      double[] a = new double[9];
      double[] bb = new double[9];
      for (int k = 0; k < edges; k++) {
        linearize(k, e, a, bb);
        int i = ei[k];
        int j = ej[k];
        double[] w = expand(k);
        // A' W A, A' W B, B' W B and the gradient parts
        accumulate(blocks, i, i, a, w, a);
        accumulate(blocks, i, j, a, w, bb);
        accumulate(blocks, j, j, bb, w, bb);
        gradient(b, i, a, w, e);
        gradient(b, j, bb, w, e);
      }
      double[] dx = solve(blocks, b, n, order);
      if (dx == null) {
        break;
      }
      double worst = 0;
      for (int p = 1; p < nodes; p++) {
        int o = 3 * (p - 1);
        x[p] -= dx[o];
        y[p] -= dx[o + 1];
        th[p] = wrap(th[p] - dx[o + 2]);
        worst = Math.max(worst, Math.max(Math.abs(dx[o]), Math.abs(dx[o + 1])));
      }
      if (worst < 1e-4) {
        break;
      }
    }
    double total = 0;
    for (int k = 0; k < edges; k++) {
      total += chi2(k);
    }
    return total;
  }

  private double[] expand(int k) {
    double[] s = einfo;
    int o = k * 6;
    return new double[] {
      s[o], s[o + 1], s[o + 2], s[o + 1], s[o + 3], s[o + 4], s[o + 2], s[o + 4], s[o + 5]
    };
  }

  /** Error and Jacobians (row-major 3x3) of edge k with respect to pose i (a) and j (b). */
  private void linearize(int k, double[] e, double[] a, double[] b) {
    error(k, e);
    int i = ei[k];
    int j = ej[k];
    double ci = Math.cos(th[i]);
    double si = Math.sin(th[i]);
    double zt = ez[k * 3 + 2];
    double cz = Math.cos(zt);
    double sz = Math.sin(zt);
    double dx = x[j] - x[i];
    double dy = y[j] - y[i];
    // M = Rz' Ri'
    double m00 = cz * ci - sz * si;
    double m01 = cz * si + sz * ci;
    double m10 = -sz * ci - cz * si;
    double m11 = -sz * si + cz * ci;
    // d(Ri')/dth * (dx, dy) = (-si dx + ci dy, -ci dx - si dy)
    double gx = -si * dx + ci * dy;
    double gy = -ci * dx - si * dy;
    a[0] = -m00;
    a[1] = -m01;
    a[2] = cz * gx + sz * gy;
    a[3] = -m10;
    a[4] = -m11;
    a[5] = -sz * gx + cz * gy;
    a[6] = 0;
    a[7] = 0;
    a[8] = -1;
    b[0] = m00;
    b[1] = m01;
    b[2] = 0;
    b[3] = m10;
    b[4] = m11;
    b[5] = 0;
    b[6] = 0;
    b[7] = 0;
    b[8] = 1;
  }

  /** blocks[p][q] += P' W Q (p, q pose indices; pose 0 left out). */
  private static void accumulate(
      Map<Long, double[]> blocks, int p, int q, double[] pm, double[] w, double[] qm) {
    if (p == 0 || q == 0) {
      return;
    }
    int r = Math.min(p, q);
    int c = Math.max(p, q);
    boolean swap = p > q;
    double[] blk = blocks.computeIfAbsent(((long) r << 32) | c, key -> new double[9]);
    for (int u = 0; u < 3; u++) {
      for (int v = 0; v < 3; v++) {
        double s = 0;
        for (int m = 0; m < 3; m++) {
          double wq = 0;
          for (int l = 0; l < 3; l++) {
            wq += w[m * 3 + l] * qm[l * 3 + v];
          }
          s += pm[m * 3 + u] * wq;
        }
        if (swap) {
          blk[v * 3 + u] += s;
        } else {
          blk[u * 3 + v] += s;
        }
      }
    }
  }

  private static void gradient(double[] b, int p, double[] pm, double[] w, double[] e) {
    if (p == 0) {
      return;
    }
    int o = 3 * (p - 1);
    for (int u = 0; u < 3; u++) {
      double s = 0;
      for (int m = 0; m < 3; m++) {
        double we = w[m * 3] * e[0] + w[m * 3 + 1] * e[1] + w[m * 3 + 2] * e[2];
        s += pm[m * 3 + u] * we;
      }
      b[o + u] += s;
    }
  }

  /**
   * Solves H dx = b with H given as upper blocks; null if H is singular. The poses are renumbered
   * by {@code order} (pose p becomes row block order[p] - 1) before the factorisation: numbered in
   * driving order, every loop closure back to the first lap would fill the factor between the two
   * poses, and a few hundred of them make it nearly dense.
   */
  private static double[] solve(Map<Long, double[]> blocks, double[] b, int n, int[] order) {
    DMatrixSparseTriplet t = new DMatrixSparseTriplet(n, n, blocks.size() * 18);
    for (Map.Entry<Long, double[]> en : blocks.entrySet()) {
      int r = order[(int) (en.getKey() >>> 32)] - 1;
      int c = order[(int) (en.getKey() & 0xffffffffL)] - 1;
      double[] blk = en.getValue();
      for (int u = 0; u < 3; u++) {
        for (int v = 0; v < 3; v++) {
          double val = blk[u * 3 + v];
          if (r == c) {
            t.addItem(3 * r + u, 3 * c + v, val + (u == v ? 1e-9 : 0));
          } else {
            t.addItem(3 * r + u, 3 * c + v, val);
            t.addItem(3 * c + v, 3 * r + u, val);
          }
        }
      }
    }
    DMatrixSparseCSC h = DConvertMatrixStruct.convert(t, (DMatrixSparseCSC) null);
    LinearSolverSparse<DMatrixSparseCSC, DMatrixRMaj> solver =
        LinearSolverFactory_DSCC.cholesky(FillReducing.NONE);
    if (!solver.setA(h)) {
      return null;
    }
    DMatrixRMaj rhs = new DMatrixRMaj(n, 1);
    int poses = n / 3 + 1;
    for (int p = 1; p < poses; p++) {
      System.arraycopy(b, 3 * (p - 1), rhs.data, 3 * (order[p] - 1), 3);
    }
    DMatrixRMaj out = new DMatrixRMaj(n, 1);
    solver.solve(rhs, out);
    double[] dx = new double[n];
    for (int p = 1; p < poses; p++) {
      System.arraycopy(out.data, 3 * (order[p] - 1), dx, 3 * (p - 1), 3);
    }
    for (double v : dx) {
      if (!Double.isFinite(v)) {
        return null;
      }
    }
    return dx;
  }
}
