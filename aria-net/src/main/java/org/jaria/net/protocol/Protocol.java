package org.jaria.net.protocol;

/**
 * Constants of ArNetworking's wire protocol (see {@code aria-net/PROTOCOL.md}): the fixed command
 * numbers of both directions, the reasons a server rejects a client, and the defaults.
 */
public final class Protocol {

  private Protocol() {}

  /** ArNetworking's default server port (TCP, and UDP on the same number). */
  public static final int DEFAULT_PORT = 7272;

  /** The version text a server sends in its introduction (ARIA sends "alpha"). */
  public static final String SERVER_VERSION = "alpha";

  /**
   * The protocol version a JAria client announces: it asks a JAria server to answer commands that
   * return nothing with an empty packet, so the client learns they were carried out (an ARIA server
   * ignores the text unless it enforces a version).
   */
  public static final String JARIA_ACK_VERSION = "JAria-ack";

  /** The first number of the data list: lower numbers are the fixed commands below. */
  public static final int FIRST_DATA_COMMAND = 256;

  // ---- commands from the server to the client (ARIA's ArServerCommands)

  /** The server closes the connection. */
  public static final int SERVER_SHUTDOWN = 1;

  /** The server introduces itself (version, UDP port, keys). */
  public static final int SERVER_INTRODUCTION = 2;

  /** Over UDP: the server's UDP introduction (its intro key). */
  public static final int SERVER_UDP_INTRODUCTION = 3;

  /** The server got the client's UDP introduction. */
  public static final int SERVER_UDP_CONFIRMATION = 4;

  /** The login was accepted. */
  public static final int SERVER_CONNECTED = 5;

  /** The login was refused: a byte2 reason ({@code REJECTED_...}) and a string. */
  public static final int SERVER_REJECTED = 6;

  /** The server will send only over TCP. */
  public static final int SERVER_TCP_ONLY = 7;

  /** The data list: numbers, names and descriptions. */
  public static final int SERVER_LIST = 129;

  /** One late addition to the data list. */
  public static final int SERVER_LIST_SINGLE = 130;

  /** The data's argument and return descriptions. */
  public static final int SERVER_LIST_ARGRET = 131;

  /** One late addition's argument and return descriptions. */
  public static final int SERVER_LIST_ARGRET_SINGLE = 132;

  /** The data's command groups and data flags. */
  public static final int SERVER_LIST_GROUP_AND_FLAGS = 133;

  /** One late addition's command group and data flags. */
  public static final int SERVER_LIST_GROUP_AND_FLAGS_SINGLE = 134;

  // ---- commands from the client to the server (ARIA's ArClientCommands)

  /** The client closes the connection. */
  public static final int CLIENT_SHUTDOWN = 1;

  /** The client's answer to the introduction: its UDP port, user and login digest. */
  public static final int CLIENT_INTRODUCTION = 2;

  /** Over UDP: the client's auth key. */
  public static final int CLIENT_UDP_INTRODUCTION = 3;

  /** The client got the server's UDP introduction. */
  public static final int CLIENT_UDP_CONFIRMATION = 4;

  /** The client wants everything over TCP. */
  public static final int CLIENT_TCP_ONLY = 5;

  /** Asks for the data list again. */
  public static final int CLIENT_LIST = 128;

  /** A request: byte2 command, byte4 interval in ms (-1: only when it changes), then arguments. */
  public static final int CLIENT_REQUEST = 129;

  /** Stops a request: byte2 command. */
  public static final int CLIENT_REQUEST_STOP = 130;

  // ---- reasons of SERVER_REJECTED

  /** Wrong user name or password. */
  public static final int REJECTED_BAD_LOGIN = 1;

  /** The robot is served through a central server. */
  public static final int REJECTED_CENTRAL_SERVER = 2;

  /** The client found the server's protocol version wrong. */
  public static final int REJECTED_CLIENT_PROTOCOL = 3;

  /** The server found the client's protocol version wrong. */
  public static final int REJECTED_SERVER_PROTOCOL = 4;

  /** Too many clients. */
  public static final int REJECTED_TOO_MANY_CLIENTS = 5;

  /** The client's type (real or simulated) is not the one the server wants. */
  public static final int REJECTED_WRONG_TYPE = 6;

  /** A name for a fixed server command, for logs. */
  public static String serverCommandName(int c) {
    return switch (c) {
      case SERVER_SHUTDOWN -> "SHUTDOWN";
      case SERVER_INTRODUCTION -> "INTRODUCTION";
      case SERVER_UDP_INTRODUCTION -> "UDP_INTRODUCTION";
      case SERVER_UDP_CONFIRMATION -> "UDP_CONFIRMATION";
      case SERVER_CONNECTED -> "CONNECTED";
      case SERVER_REJECTED -> "REJECTED";
      case SERVER_TCP_ONLY -> "TCP_ONLY";
      case SERVER_LIST -> "LIST";
      case SERVER_LIST_SINGLE -> "LISTSINGLE";
      case SERVER_LIST_ARGRET -> "LISTARGRET";
      case SERVER_LIST_ARGRET_SINGLE -> "LISTARGRETSINGLE";
      case SERVER_LIST_GROUP_AND_FLAGS -> "LISTGROUPANDFLAGS";
      case SERVER_LIST_GROUP_AND_FLAGS_SINGLE -> "LISTGROUPANDFLAGSSINGLE";
      default -> "command " + c;
    };
  }
}
