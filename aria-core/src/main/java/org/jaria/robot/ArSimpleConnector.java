package org.jaria.robot;

import org.jaria.util.ArArgumentParser;

/**
 * ARIA's older name for {@link ArRobotConnector}, kept so programs written for it (the thesis's
 * examples among them) port unchanged.
 */
public class ArSimpleConnector extends ArRobotConnector {

  /** A connector taking options from {@code args}; pass the robot to {@code connectRobot}. */
  public ArSimpleConnector(String[] args) {
    super(new ArArgumentParser(args), null);
  }

  /** A connector taking options from {@code parser}; pass the robot to {@code connectRobot}. */
  public ArSimpleConnector(ArArgumentParser parser) {
    super(parser, null);
  }

  /** A connector for {@code robot} taking options from {@code parser}. */
  public ArSimpleConnector(ArArgumentParser parser, ArRobot robot) {
    super(parser, robot);
  }
}
