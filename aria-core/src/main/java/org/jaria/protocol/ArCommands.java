package org.jaria.protocol;

/**
 * Every ARCOS client command, with its number and argument kind (ARIA's {@code ArCommands}).
 *
 * <p>Use with the direct-command methods of ArRobot, e.g. {@code robot.comInt(ArCommands.ENABLE,
 * 1)}. Commands 224 and up exist only in simulators (MobileSim and ours).
 */
public enum ArCommands {
  /** Keep-alive; also SYNC0 during the handshake. */
  PULSE(0, ArgKind.NONE),
  /** Starts the robot's servers (SIPs, sonar, motors controller); also SYNC1 in the handshake. */
  OPEN(1, ArgKind.INT),
  /** Ends the session, disabling motors and sonar; also SYNC2 in the handshake. */
  CLOSE(2, ArgKind.NONE),
  /** Sonar firing sequence: a string of sonar numbers 1..32; empty disables all. */
  POLLING(3, ArgKind.STRING),
  /** Motors on (1) or off (0). */
  ENABLE(4, ArgKind.INT),
  /** Translational acceleration (+) or deceleration (−), mm/s². */
  SETA(5, ArgKind.INT),
  /** Maximum translational velocity, mm/s. */
  SETV(6, ArgKind.INT),
  /** Resets odometry to 0,0,0 (simulators also take x, y, th). */
  SETO(7, ArgKind.NONE),
  /** Drives a distance, mm, at the SETV speed. */
  MOVE(8, ArgKind.INT),
  /** Rotational velocity, deg/s (older name of RVEL). */
  ROTATE(9, ArgKind.INT),
  /** Maximum rotational velocity, deg/s. */
  SETRV(10, ArgKind.INT),
  /** Translational velocity, mm/s. */
  VEL(11, ArgKind.INT),
  /** Absolute heading, degrees (+ counter-clockwise), turning the shortest way. */
  HEAD(12, ArgKind.INT),
  /** Heading relative to the current heading, degrees. */
  DHEAD(13, ArgKind.INT),
  /** Obsolete relative rotation. */
  DROTATE(14, ArgKind.INT),
  /** Plays tones: up to 20 (duration in 20 ms units, MIDI note) byte pairs. */
  SAY(15, ArgKind.STRING),
  /** Requests JOYSTICKpac: 0 stop, 1 one, 2 continuous (ARIA: JOYINFO). */
  JOYREQUEST(17, ArgKind.INT),
  /** Requests a CONFIGpac. */
  CONFIG(18, ArgKind.INT),
  /** Requests ENCODERpac: 0 stop, 1 one, 2 continuous. */
  ENCODER(19, ArgKind.INT),
  /** Maximum rotational velocity per direction: + counter-clockwise, − clockwise. */
  SETRVDIR(20, ArgKind.INT),
  /** Rotational velocity, deg/s (+ counter-clockwise). */
  RVEL(21, ArgKind.INT),
  /** Heading relative to the last heading setpoint, degrees. */
  DCHEAD(22, ArgKind.INT),
  /** Rotational acceleration (+) or deceleration (−), deg/s². */
  SETRA(23, ArgKind.INT),
  /** Sonar on/off: bit 0 enable, bits 1..3 array number (0 = all). */
  SONAR(28, ArgKind.INT),
  /** Stops the robot; motors stay enabled. */
  STOP(29, ArgKind.NONE),
  /** Digital outputs: high byte mask, low byte states. */
  DIGOUT(30, ArgKind.TWO_BYTES),
  /** Wheel velocities: high byte left, low byte right, signed, times Vel2Divisor mm/s. */
  VEL2(32, ArgKind.TWO_BYTES),
  /** Gripper command (1 open, 2 close, 3 stop, 4 lift up, 5 lift down, 6 lift stop, ...). */
  GRIPPER(33, ArgKind.INT),
  /** Selects the analog port reported in the SIP. */
  ADSEL(35, ArgKind.INT),
  /** Gripper parameter value (for GRIPPER 16/17). */
  GRIPPERVAL(36, ArgKind.INT),
  /** Requests GRIPPERpac: 0 stop, 1 one, 2 continuous. */
  GRIPREQUEST(37, ArgKind.INT),
  /** Gyro clockwise calibration factor. */
  GYROCALCW(38, ArgKind.UINT),
  /** Gyro counter-clockwise calibration factor. */
  GYROCALCCW(39, ArgKind.UINT),
  /** Requests IOpac: 0 stop, 1 one, 2 continuous. */
  IOREQUEST(40, ArgKind.INT),
  /** Pan/tilt unit position (old accessory). */
  PTUPOS(41, ArgKind.TWO_BYTES),
  /** Sends a string out of the AUX1 serial port. */
  TTY2(42, ArgKind.STRING),
  /** Requests 1..200 bytes from AUX1 as SERAUXpac (0 flushes). */
  GETAUX(43, ArgKind.UINT),
  /** Stall on bumper hit: 0 none, 1 front, 2 rear, 3 both. */
  BUMPSTALL(44, ArgKind.INT),
  /** TCM2 compass mode 0..7. */
  TCM2(45, ArgKind.INT),
  /** Joystick drives the robot: 1 on, 0 off. */
  JOYDRIVE(47, ArgKind.INT),
  /** Sonar cycle time, ms (2..120). */
  SONARCYCLE(48, ArgKind.UINT),
  /** Host serial baud (0=9600 ... 4=115200). */
  HOSTBAUD(50, ArgKind.INT),
  /** AUX1 baud. */
  AUX1BAUD(51, ArgKind.INT),
  /** AUX2 baud. */
  AUX2BAUD(52, ArgKind.INT),
  /** AUX3 baud. */
  AUX3BAUD(53, ArgKind.INT),
  /** Emergency stop: stop with maximum deceleration; stays stopped until a new motion command. */
  E_STOP(55, ArgKind.NONE),
  /** Stall on E-stop / motor stall settings. */
  M_STALL(56, ArgKind.INT),
  /** Gyro packets (client-side gyro: 0/1/2) or server-side gyro (0 off, 1 on). */
  GYRO(58, ArgKind.INT),
  /** Writes to the LCD. */
  LCDWRITE(59, ArgKind.STRING),
  /** Sends a string out of AUX3. */
  TTY4(60, ArgKind.STRING),
  /** Requests bytes from AUX3. */
  GETAUX3(61, ArgKind.UINT),
  /** Battery information request. */
  BATTERYINFO(62, ArgKind.INT),
  /** Sends a string out of AUX2. */
  TTY3(66, ArgKind.STRING),
  /** Requests bytes from AUX2. */
  GETAUX2(67, ArgKind.UINT),
  /** Charger: 0 retract, 1 deploy. */
  CHARGE(68, ArgKind.INT),
  /** Arm: information packet request. */
  ARM_INFO(70, ArgKind.NONE),
  /** Arm: status packets. */
  ARM_STATUS(71, ArgKind.INT),
  /** Arm: initialise. */
  ARM_INIT(72, ArgKind.NONE),
  /** Arm: check. */
  ARM_CHECK(73, ArgKind.NONE),
  /** Arm: power. */
  ARM_POWER(74, ArgKind.INT),
  /** Arm: home. */
  ARM_HOME(75, ArgKind.INT),
  /** Arm: park. */
  ARM_PARK(76, ArgKind.NONE),
  /** Arm: joint position. */
  ARM_POS(77, ArgKind.TWO_BYTES),
  /** Arm: joint speed. */
  ARM_SPEED(78, ArgKind.TWO_BYTES),
  /** Arm: stop. */
  ARM_STOP(79, ArgKind.INT),
  /** Arm: auto-park timeout. */
  ARM_AUTOPARK(80, ArgKind.INT),
  /** Arm: gripper park timeout. */
  ARM_GRIPPARK(81, ArgKind.INT),
  /** Rotation PID proportional gain. */
  ROTKP(82, ArgKind.INT),
  /** Rotation PID derivative gain. */
  ROTKV(83, ArgKind.INT),
  /** Rotation PID integral gain. */
  ROTKI(84, ArgKind.INT),
  /** Translation PID proportional gain. */
  TRANSKP(85, ArgKind.INT),
  /** Translation PID derivative gain. */
  TRANSKV(86, ArgKind.INT),
  /** Translation PID integral gain. */
  TRANSKI(87, ArgKind.INT),
  /** Encoder ticks per wheel revolution. */
  REVCOUNT(88, ArgKind.UINT),
  /** Drift factor in 1/8192 units. */
  DRIFTFACTOR(89, ArgKind.INT),
  /** Buzzer sounds on/off. */
  SOUNDTOG(92, ArgKind.INT),
  /** Encoder ticks per mm. */
  TICKSMM(93, ArgKind.UINT),
  /** Move the simulated robot to a true pose: a type byte, then x, y, th as int32 (mm, deg). */
  SIM_SET_POSE(224, ArgKind.SPECIAL),
  /** Move the simulated robot back to its start and reset odometry. */
  SIM_RESET(225, ArgKind.NONE),
  /** Simulated laser: 0 off, 1 packets 0x60, 2 extended packets 0x61. */
  SIM_LRF_ENABLE(230, ArgKind.INT),
  /** Simulated laser field-of-view start, degrees. */
  SIM_LRF_SET_FOV_START(231, ArgKind.INT),
  /** Simulated laser field-of-view end, degrees. */
  SIM_LRF_SET_FOV_END(232, ArgKind.INT),
  /** Simulated laser angular resolution, hundredths of a degree. */
  SIM_LRF_SET_RES(233, ArgKind.INT),
  /** Simulator meta-operation: an int16 op code, then op-specific data (1 = load map). */
  SIM_CTRL(236, ArgKind.SPECIAL),
  /** Requests SIMSTAT (0x62): none or 1 one packet, 2 before each SIP, 0 stop. */
  SIM_STAT(237, ArgKind.INT),
  /** Shows a message in the simulator: a length byte and the characters. */
  SIM_MESSAGE(238, ArgKind.SPECIAL),
  /** Makes the simulator exit with the given code. */
  SIM_EXIT(239, ArgKind.INT),
  /** Artificial battery voltage, decivolts (0 = real). */
  BATTEST(250, ArgKind.INT),
  /** Resets the controller. */
  RESET(253, ArgKind.NONE),
  /** Enters maintenance mode. */
  MAINTENANCE(255, ArgKind.NONE);

  /** ARIA's name for {@link #JOYREQUEST}. */
  public static final ArCommands JOYINFO = JOYREQUEST;

  /** ARIA's name for {@link #GRIPREQUEST}. */
  public static final ArCommands GRIPPERPACREQUEST = GRIPREQUEST;

  /** The spec's other name for command 56, {@link #M_STALL}. */
  public static final ArCommands E_STALL = M_STALL;

  /** ARIA's name for command 56, {@link #M_STALL}. */
  public static final ArCommands ESTALL = M_STALL;

  /** ARIA's name for {@link #E_STOP}. */
  public static final ArCommands ESTOP = E_STOP;

  /** ARIA's name for {@link #GYRO}. */
  public static final ArCommands GYROREQUEST = GYRO;

  /** Handshake commands share numbers with PULSE, OPEN and CLOSE. */
  public static final int SYNC0 = 0;

  /** Second handshake packet. */
  public static final int SYNC1 = 1;

  /** Third handshake packet; the robot's echo carries name, type and subtype. */
  public static final int SYNC2 = 2;

  private static final ArCommands[] BY_NUMBER = new ArCommands[256];

  static {
    for (ArCommands c : values()) {
      BY_NUMBER[c.number] = c;
    }
  }

  private final int number;
  private final ArgKind argKind;

  ArCommands(int number, ArgKind argKind) {
    this.number = number;
    this.argKind = argKind;
  }

  /** The command number sent as the packet ID. */
  public int getNumber() {
    return number;
  }

  /** What argument the command takes. */
  public ArgKind getArgKind() {
    return argKind;
  }

  /** The command with this number, or {@code null} if ARCOS has none. */
  public static ArCommands fromNumber(int number) {
    return number >= 0 && number < 256 ? BY_NUMBER[number] : null;
  }
}
