package org.jaria.web.foxglove;

import java.util.List;

/** One message from a client, as read by {@link ClientMessages}. */
public sealed interface ClientRequest {

  /**
   * {@code subscribe}: send me these channels under these subscription ids.
   *
   * @param subscriptions (subscription id, channel id) pairs
   */
  record Subscribe(List<Subscription> subscriptions) implements ClientRequest {
    /** Copies. */
    public Subscribe {
      subscriptions = List.copyOf(subscriptions);
    }
  }

  /**
   * One subscription.
   *
   * @param id the client's id for it
   * @param channelId the channel
   */
  record Subscription(long id, long channelId) {}

  /**
   * {@code unsubscribe}.
   *
   * @param subscriptionIds the subscriptions to end
   */
  record Unsubscribe(List<Long> subscriptionIds) implements ClientRequest {
    /** Copies. */
    public Unsubscribe {
      subscriptionIds = List.copyOf(subscriptionIds);
    }
  }

  /**
   * {@code advertise}: the client will publish on these channels (client publish).
   *
   * @param channels the client's channels
   */
  record Advertise(List<ClientChannel> channels) implements ClientRequest {
    /** Copies. */
    public Advertise {
      channels = List.copyOf(channels);
    }
  }

  /**
   * A channel a client publishes on.
   *
   * @param id the client's id for it
   * @param topic its topic
   * @param encoding its message encoding
   * @param schemaName its schema's name
   */
  record ClientChannel(long id, String topic, String encoding, String schemaName) {}

  /**
   * {@code unadvertise}.
   *
   * @param channelIds the client's channels it stops publishing on
   */
  record Unadvertise(List<Long> channelIds) implements ClientRequest {
    /** Copies. */
    public Unadvertise {
      channelIds = List.copyOf(channelIds);
    }
  }

  /**
   * A binary client message: data on one of the client's channels.
   *
   * @param channelId the client's channel
   * @param payload the message (JSON for this server)
   */
  // Read once by the control that handles it.
  @SuppressWarnings("ArrayRecordComponent")
  record Publish(long channelId, byte[] payload) implements ClientRequest {}

  /**
   * A well-formed message with an operation this server does not do.
   *
   * @param op the operation's name
   */
  record Unknown(String op) implements ClientRequest {}

  /**
   * Not a message at all.
   *
   * @param reason what is wrong with it
   */
  record Malformed(String reason) implements ClientRequest {}
}
