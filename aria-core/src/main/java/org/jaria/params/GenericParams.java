package org.jaria.params;

/**
 * The built-in bottom layer of every {@link ArRobotParams}: the values ARIA's ArRobotParams
 * constructor uses for a generic Pioneer, written as a parameter file so that the typed layer
 * always finds every keyword it knows.
 */
final class GenericParams {

  /** Source name used in messages and {@link ArRobotParams#getSources()}. */
  static final String SOURCE = "<built-in generic Pioneer defaults>";

  /*
   * Two deliberate differences from ARIA's constructor: ARIA leaves MaxVelocity and MaxRVelocity
   * at 0 ("ask the robot's CONFIG packet") and never initialises DiffConvFactor. Here the Pioneer 3
   * DX figures are used instead, so code that needs a limit before (or without) a CONFIG packet
   * gets a usable one. No sonars are defined: their positions depend on the model.
   */
  static final String TEXT =
      """
      ConfigVersion 2.0
      ; JAria built-in defaults for a robot whose model has no parameter file.

      Section General settings
      Class Pioneer            ; general type of robot
      Subclass                 ; specific type of robot (unknown)
      RobotRadius 250          ; radius in mm
      RobotDiagonal 120        ; half-height to diagonal of octagon
      RobotWidth 400           ; width in mm
      RobotLength 500          ; length in mm
      RobotLengthFront 0       ; 0: half of RobotLength
      RobotLengthRear 0        ; 0: half of RobotLength
      Holonomic true           ; turns in place
      MaxRVelocity 500         ; absolute maximum deg/s (ARIA: 0, use CONFIG)
      MaxVelocity 2200         ; absolute maximum mm/s (ARIA: 0, use CONFIG)
      MaxLatVelocity 0         ; no lateral motion
      HasMoveCommand true      ; firmware knows MOVE
      RequestIOPackets false
      RequestEncoderPackets false
      SwitchToBaudRate 38400

      Section Conversion factors
      AngleConvFactor 0.001534 ; radians per angle unit (2 pi / 4096)
      DistConvFactor 1.0       ; mm per distance unit
      VelConvFactor 1.0        ; mm/s per velocity unit
      RangeConvFactor 1.0      ; mm per sonar range unit
      DiffConvFactor 0.0056    ; wheel speed difference to angular speed
      Vel2Divisor 20           ; VEL2 units
      GyroScaler 1.626         ; gyro rate scale

      Section Accessories the robot has
      TableSensingIR false
      NewTableSensingIR false
      FrontBumpers false
      NumFrontBumpers 5
      RearBumpers false
      NumRearBumpers 5

      Section IR parameters
      IRNum 0

      Section Movement control parameters
      SettableVelMaxes true
      TransVelMax 0            ; 0: keep the robot's own value
      RotVelMax 0
      SettableAccsDecs true
      TransAccel 0
      TransDecel 0
      RotAccel 0
      RotDecel 0
      HasLatVel false
      LatVelMax 0
      LatAccel 0
      LatDecel 0

      Section GPS parameters
      GPSPX 0
      GPSPY 0
      GPSType standard
      GPSPort COM2
      GPSBaud 9600

      Section Compass parameters
      CompassType robot
      CompassPort

      Section Sonar parameters
      SonarNum 0

      Section Laser parameters
      LaserAutoConnect false
      LaserX 0
      LaserY 0
      LaserTh 0
      LaserMaxRange 0
      """;

  private GenericParams() {}
}
