package org.jaria.net;

import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.jaria.net.client.ArClientException;

/** Results of the client library's futures in tests. */
public final class Futures {

  private Futures() {}

  /** The value, waiting at most 20 s. */
  public static <T> T get(CompletableFuture<T> f) throws Exception {
    return f.get(20, TimeUnit.SECONDS);
  }

  /** The {@link ArClientException} the future failed with (fails the test if it did not). */
  public static ArClientException failure(CompletableFuture<?> f) {
    ExecutionException e =
        assertThrows(ExecutionException.class, () -> f.get(20, TimeUnit.SECONDS));
    return assertInstanceOf(ArClientException.class, e.getCause());
  }
}
