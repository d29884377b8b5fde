package org.jaria.robot;

import java.util.List;

/**
 * What state reflection decided in one cycle: the motion commands to send, in order, and what
 * follows from them.
 *
 * @param commands the commands to send this cycle, in order (often none)
 * @param direct the motion-command request afterwards: a {@code move} that went out is now being
 *     driven, and one driven by velocity ends as a stop
 * @param memory what to remember for the next cycle
 * @param tryingToMove whether the commands ask the robot to move
 */
record CycleCommands(
    List<MotionCommand> commands,
    DirectMotion direct,
    ReflectionMemory memory,
    boolean tryingToMove) {}
