package org.jaria.net.server.info;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.jaria.net.data.PopupInfo;
import org.junit.jupiter.api.Test;

class PopupBookTest {

  private static PopupInfo timed(int seconds) {
    return new PopupInfo(
        "",
        "t",
        "m",
        PopupInfo.PopupType.INFORMATION,
        0,
        0,
        seconds,
        "timed out",
        "OK",
        "ok",
        "",
        "",
        "",
        "");
  }

  @Test
  void numbersClicksClosesAndTimeouts() {
    PopupBook b = new PopupBook();
    int a = b.create(timed(0), 0);
    int c = b.create(timed(5), 1000);
    assertEquals(List.of(1, 2), List.of(a, c));
    assertEquals(List.of(), b.expire(5999), "5 s not yet over");
    assertEquals(List.of(new PopupBook.Done(2, -1, "timed out")), b.expire(6000));
    assertEquals(List.of(), b.expire(1_000_000), "a popup without timeout stays");
    assertEquals(new PopupBook.Done(1, 0, "ok"), b.click(1, 0));
    assertNull(b.click(1, 0), "already closed");
    assertNull(b.close(42, "x"), "never opened");
    int d = b.create(timed(0), 0);
    assertEquals(new PopupBook.Done(d, -2, "bye"), b.close(d, "bye"));
    assertEquals(List.of(), b.open());
  }
}
