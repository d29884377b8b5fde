package org.jaria.net.server;

import org.jaria.net.ArNetPacket;

/**
 * Answers one request (ArNetworking's data callback). Read the arguments from {@code request} in
 * order and write the reply into {@code reply}; the server sends the reply as the response (an
 * empty reply acknowledges a command).
 *
 * <p>Throwing reports an error to that client only: an {@link org.jaria.net.ArNetPacketException}
 * (wrong or missing arguments) as "bad arguments", a {@link NetRequestException} with its own code,
 * anything else as "failed" with the exception's message.
 */
@FunctionalInterface
public interface RequestHandler {

  /** Handles one request. */
  void handle(ArServerClient client, ArNetPacket request, ArNetPacket reply) throws Exception;
}
