package org.jaria.action;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;

/**
 * Finds a triangular target — two straight sides meeting at a vertex that points at the robot, like
 * the target on a docking station — among the lines of a laser scan, as {@link
 * ArActionTriangleDriveTo} does. Each pair of consecutive lines is a candidate: its sides must be
 * within 125 mm of the expected lengths, its angle within 15° of the expected one, and the gap
 * between them under 100 mm. Candidates are scored by how well they match and where they are: when
 * first looking, targets straight ahead, facing the robot and near its line of travel score higher;
 * later, targets near where the vertex was last seen score higher. The best candidate scoring at
 * least 5 wins.
 *
 * <p>The vertex found is a pose: its position is where the two sides cross, its heading points out
 * of the triangle, along the bisector of its sides (towards the robot that sees it).
 */
public class TriangleFinder {

  private double line1Length = 254;
  private double angleBetween = 135;
  private double line2Length = 254;
  private double maxLateralDist;
  private double maxAngleMisalignment;

  /** A finder for ARIA's default target: two 254 mm sides at 135°. */
  public TriangleFinder() {}

  /**
   * Sets the target's shape; a value of 0 is not checked.
   *
   * @param line1Length length of the first side scanned, mm
   * @param angleBetween angle between the sides, degrees (negative: an inverted triangle, whose
   *     vertex points away)
   * @param line2Length length of the second side, mm
   */
  public void setTriangleParams(double line1Length, double angleBetween, double line2Length) {
    this.line1Length = line1Length;
    this.angleBetween = angleBetween;
    this.line2Length = line2Length;
  }

  /** Ignores vertices farther than this from the robot's line of travel, mm (0: no limit). */
  public void setMaxLateralDist(double mm) {
    maxLateralDist = mm;
  }

  /**
   * Ignores vertices whose facing differs from the robot's original heading (reversed) by more than
   * this, degrees (0: no limit).
   */
  public void setMaxAngleMisalignment(double degrees) {
    maxAngleMisalignment = degrees;
  }

  /** A found vertex with its score. */
  public record Vertex(ArPose pose, double score, int lineIndex) {}

  /**
   * The best vertex among consecutive pairs of {@code lines}, or null.
   *
   * @param lines lines in sweep order ({@link ArLineFinder#getLines})
   * @param robot the robot's global pose
   * @param initial true when first looking for the target; false to prefer {@code lastVertex}
   * @param goStraight (when not initial) prefer vertices straight ahead of the robot
   * @param lastVertex where the vertex was last seen (global), used when not initial
   * @param originalAngle the robot's heading when the search started (for the misalignment check)
   */
  public Vertex find(
      List<ArLineFinderSegment> lines,
      ArPose robot,
      boolean initial,
      boolean goStraight,
      ArPose lastVertex,
      double originalAngle) {
    Vertex best = null;
    for (int i = 0; i + 1 < lines.size(); i++) {
      ArLineFinderSegment l1 = lines.get(i);
      ArLineFinderSegment l2 = lines.get(i + 1);
      double gap = l1.getEndPoint2().findDistanceTo(l2.getEndPoint1());
      double between = ArMath.subAngle(180, ArMath.subAngle(l1.getLineAngle(), l2.getLineAngle()));
      double angleDelta = angleBetween != 0 ? Math.abs(ArMath.subAngle(between, angleBetween)) : 0;
      double line1Delta = line1Length != 0 ? Math.abs(l1.getLength() - line1Length) : 0;
      double line2Delta = line2Length != 0 ? Math.abs(l2.getLength() - line2Length) : 0;
      if (line1Delta > 125 || line2Delta > 125 || angleDelta > 15 || gap > 100) {
        continue;
      }
      ArPose cross = l1.intersection(l2);
      if (cross == null) {
        continue;
      }
      double th = ArMath.addAngle(l1.getLineAngle(), between / 2);
      if (angleBetween <= -.1) {
        th = ArMath.addAngle(180, th);
      }
      ArPose vertex = cross.withTh(th);
      double r = Math.toRadians(th);
      ArLineSegment vertexLine =
          new ArLineSegment(
              vertex.x(),
              vertex.y(),
              vertex.x() + Math.cos(r) * 20000,
              vertex.y() + Math.sin(r) * 20000);
      if (maxLateralDist > 0) {
        double rr = Math.toRadians(robot.th());
        ArLineSegment robotLine =
            new ArLineSegment(
                robot.x(),
                robot.y(),
                robot.x() + Math.cos(rr) * 20000,
                robot.y() + Math.sin(rr) * 20000);
        if (robotLine.getDistToLine(vertex.x(), vertex.y()) > maxLateralDist) {
          continue;
        }
      }
      if (maxAngleMisalignment > 0
          && Math.abs(ArMath.subAngle(ArMath.subAngle(originalAngle, 180), th))
              > maxAngleMisalignment) {
        continue;
      }

      double score = 10 - line1Delta / 25 + 10 - line2Delta / 25 + 10 - angleDelta / 2;
      if (initial) {
        double off = Math.abs(ArMath.subAngle(robot.th(), robot.findAngleTo(vertex)));
        score *= .5 + .5 * (30 - off) / 30;
        score *= .5 + .5 * (1500 - vertexLine.getDistToLine(robot.x(), robot.y())) / 1500;
        // ARIA leaves out the "/ 30" here, so facing the robot weighs far more than the other
        // factors and a target turned more than about 30° away is rejected; kept as it is.
        score *= .5 + .5 * (30 - Math.abs(ArMath.subAngle(th, vertex.findAngleTo(robot))));
      } else {
        double dist = lastVertex == null ? 0 : lastVertex.findDistanceTo(vertex);
        // ARIA's ladder missed an "else", so even a vertex within 100 mm got the 0.8 factor.
        if (dist < 100) {
          score *= 1;
        } else if (dist < 200) {
          score *= .8;
        } else if (dist < 400) {
          score *= .5;
        } else if (dist < 600) {
          score *= .2;
        } else if (dist < 800) {
          score *= .1;
        } else {
          score = 0;
        }
        double fromLast = lastVertex == null ? 0 : Math.abs(ArMath.subAngle(lastVertex.th(), th));
        if (fromLast < 5) {
          score *= 1;
        } else if (fromLast < 10) {
          score *= .75;
        } else if (fromLast < 20) {
          score *= .5;
        } else if (fromLast < 30) {
          score *= .25;
        } else {
          score = 0;
        }
        if (goStraight) {
          double a = Math.abs(ArMath.subAngle(robot.findAngleTo(vertex), robot.th()));
          if (a < 2) {
            score *= 1;
          } else if (a < 5) {
            score *= .5;
          } else if (a < 10) {
            score *= .1;
          } else {
            score = 0;
          }
        }
      }
      if (score < 5) {
        continue;
      }
      if (best == null || score > best.score()) {
        best = new Vertex(vertex, score, i);
      }
    }
    return best;
  }
}
