package org.jaria.web.foxglove;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * One client's side of the protocol: its subscriptions, the channels it publishes on, and how fast
 * it may send. It decides what to do with each request and says so in an {@link Outcome}; sending
 * is the transport's job. Requests come from one network thread at a time; the publisher reads the
 * subscriptions from another, through an immutable copy.
 */
public final class ClientSession {

  /** Most subscriptions one client may hold. */
  public static final int MAX_SUBSCRIPTIONS = 256;

  /** Most channels one client may publish on. */
  public static final int MAX_CLIENT_CHANNELS = 8;

  /** Requests a client may send in a burst. */
  public static final int BURST = 100;

  /** Requests per second a client may keep sending. */
  public static final int PER_SECOND = 50;

  /** What the transport should count, if anything. */
  public enum Problem {
    /** Not a message of the protocol (or over a JSON limit). */
    MALFORMED,
    /** An operation this server does not do. */
    UNKNOWN_OP,
    /** Refused: over a limit, no such channel, or control not allowed. */
    REFUSED,
    /** Too many requests too fast: dropped unread. */
    FLOOD
  }

  /**
   * What a request leads to.
   *
   * @param replies status messages to send back (JSON text)
   * @param subscribed channels newly subscribed to (a latched topic's last message goes to them)
   * @param published a message the client published (a control command), or null
   * @param problem what to count, or null
   */
  public record Outcome(
      List<String> replies, List<Long> subscribed, Published published, Problem problem) {
    /** Copies. */
    public Outcome {
      replies = List.copyOf(replies);
      subscribed = List.copyOf(subscribed);
    }

    static Outcome problem(Problem p, String reply) {
      return new Outcome(
          List.of(ServerMessages.status(ServerMessages.Level.WARNING, reply)), List.of(), null, p);
    }

    static final Outcome NOTHING = new Outcome(List.of(), List.of(), null, null);
  }

  /**
   * A message a client published on one of its channels.
   *
   * @param topic the channel's topic
   * @param payload the message
   */
  // Handed once to the control that reads it.
  @SuppressWarnings("ArrayRecordComponent")
  public record Published(String topic, byte[] payload) {}

  private final boolean mayPublish;

  @GuardedBy("this")
  private final Map<Long, Long> channelBySubscription = new HashMap<>();

  @GuardedBy("this")
  private final Map<Long, String> clientTopics = new HashMap<>();

  /** Written under the lock, read by the publisher without it. */
  private volatile Map<Long, Long> subscriptionByChannel = Map.of();

  @GuardedBy("this")
  private double tokens = BURST;

  @GuardedBy("this")
  private long lastRefill = Long.MIN_VALUE;

  /**
   * @param mayPublish whether this client may publish (control allowed, and trusted)
   */
  public ClientSession(boolean mayPublish) {
    this.mayPublish = mayPublish;
  }

  /**
   * Whether a request arriving at {@code nowNanos} may be handled: a token bucket of {@link #BURST}
   * requests refilled at {@link #PER_SECOND} a second.
   */
  public synchronized boolean admit(long nowNanos) {
    if (lastRefill == Long.MIN_VALUE) {
      lastRefill = nowNanos;
    }
    tokens = Math.min(BURST, tokens + (nowNanos - lastRefill) * 1e-9 * PER_SECOND);
    lastRefill = nowNanos;
    if (tokens < 1) {
      return false;
    }
    tokens -= 1;
    return true;
  }

  /** Handles one request against the channels the server advertises now. */
  public synchronized Outcome handle(ClientRequest request, List<Channel> channels) {
    if (request instanceof ClientRequest.Malformed m) {
      return Outcome.problem(Problem.MALFORMED, "malformed message: " + m.reason());
    }
    if (request instanceof ClientRequest.Unknown u) {
      return Outcome.problem(Problem.UNKNOWN_OP, "unsupported operation: " + u.op());
    }
    if (request instanceof ClientRequest.Subscribe s) {
      return subscribe(s, channels);
    }
    if (request instanceof ClientRequest.Unsubscribe u) {
      for (Long id : u.subscriptionIds()) {
        channelBySubscription.remove(id);
      }
      publishSubscriptions();
      return Outcome.NOTHING;
    }
    if (request instanceof ClientRequest.Advertise a) {
      return advertise(a);
    }
    if (request instanceof ClientRequest.Unadvertise u) {
      u.channelIds().forEach(clientTopics::remove);
      return Outcome.NOTHING;
    }
    ClientRequest.Publish p = (ClientRequest.Publish) request;
    String topic = clientTopics.get(p.channelId());
    if (topic == null) {
      return Outcome.problem(
          Problem.REFUSED, "no client channel " + p.channelId() + ": advertise it first");
    }
    return new Outcome(List.of(), List.of(), new Published(topic, p.payload()), null);
  }

  @GuardedBy("this")
  private Outcome subscribe(ClientRequest.Subscribe s, List<Channel> channels) {
    List<Long> added = new ArrayList<>();
    List<String> replies = new ArrayList<>();
    for (ClientRequest.Subscription sub : s.subscriptions()) {
      if (!hasChannel(channels, sub.channelId())) {
        replies.add(warning("no channel " + sub.channelId()));
      } else if (channelBySubscription.size() >= MAX_SUBSCRIPTIONS
          && !channelBySubscription.containsKey(sub.id())) {
        replies.add(warning("at most " + MAX_SUBSCRIPTIONS + " subscriptions"));
      } else {
        // One subscription per channel: a second one to the same channel replaces the first.
        channelBySubscription.values().remove(sub.channelId());
        channelBySubscription.put(sub.id(), sub.channelId());
        added.add(sub.channelId());
      }
    }
    publishSubscriptions();
    return new Outcome(replies, added, null, replies.isEmpty() ? null : Problem.REFUSED);
  }

  @GuardedBy("this")
  private Outcome advertise(ClientRequest.Advertise a) {
    if (!mayPublish) {
      return Outcome.problem(
          Problem.REFUSED, "this server is read-only (start it with --allow-control to drive)");
    }
    List<String> replies = new ArrayList<>();
    for (ClientRequest.ClientChannel c : a.channels()) {
      if (!"json".equals(c.encoding())) {
        replies.add(warning("channel " + c.topic() + ": only json encoding is accepted"));
      } else if (clientTopics.size() >= MAX_CLIENT_CHANNELS && !clientTopics.containsKey(c.id())) {
        replies.add(warning("at most " + MAX_CLIENT_CHANNELS + " client channels"));
      } else {
        clientTopics.put(c.id(), c.topic());
      }
    }
    return new Outcome(replies, List.of(), null, replies.isEmpty() ? null : Problem.REFUSED);
  }

  private static boolean hasChannel(List<Channel> channels, long id) {
    for (Channel c : channels) {
      if (c.id() == id) {
        return true;
      }
    }
    return false;
  }

  private static String warning(String text) {
    return ServerMessages.status(ServerMessages.Level.WARNING, text);
  }

  @GuardedBy("this")
  private void publishSubscriptions() {
    Map<Long, Long> inverse = new HashMap<>();
    channelBySubscription.forEach((sub, channel) -> inverse.put(channel, sub));
    subscriptionByChannel = Map.copyOf(inverse);
  }

  /** The client's subscription id for {@code channelId}, or -1 if it has none. */
  public long subscriptionFor(long channelId) {
    Long sub = subscriptionByChannel.get(channelId);
    return sub == null ? -1 : sub;
  }

  /** How many subscriptions the client holds. */
  public int subscriptionCount() {
    return subscriptionByChannel.size();
  }

  /** Forgets the subscriptions to channels that are gone. */
  public synchronized void channelsRemoved(List<Channel> removed) {
    for (Channel c : removed) {
      channelBySubscription.values().remove((long) c.id());
    }
    publishSubscriptions();
  }
}
