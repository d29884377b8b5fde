package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Which commands are carried out for which clients, as values. */
class CommandPolicyTest {

  private static final int SIM_SET_POSE = 224;
  private static final int SIM_CTRL = 236;
  private static final int SIM_EXIT = 239;
  private static final int VEL = 11;

  @Test
  void byDefaultOnlyClientsOnThisMachineMayEndTheSimulatorOrLoadMaps() {
    CommandPolicy p = CommandPolicy.DEFAULT;
    for (ClientKind local : new ClientKind[] {ClientKind.IN_MEMORY, ClientKind.LOOPBACK_TCP}) {
      assertNull(p.refusal(SIM_EXIT, -1, local));
      assertNull(p.refusal(SIM_CTRL, 1, local));
      assertNull(p.refusal(SIM_CTRL, 2, local));
    }
    assertEquals(
        IgnoredCommand.Reason.REMOTE_CLIENT, p.refusal(SIM_EXIT, -1, ClientKind.REMOTE_TCP));
    assertEquals(
        IgnoredCommand.Reason.REMOTE_CLIENT, p.refusal(SIM_CTRL, 1, ClientKind.REMOTE_TCP));
    assertEquals(
        IgnoredCommand.Reason.REMOTE_CLIENT, p.refusal(SIM_CTRL, 2, ClientKind.REMOTE_TCP));
    assertNull(p.refusal(SIM_CTRL, 6, ClientKind.REMOTE_TCP), "SIM_INFO is harmless");
    assertNull(p.refusal(SIM_SET_POSE, -1, ClientKind.REMOTE_TCP), "teleport as MobileSim");
    assertNull(p.refusal(VEL, -1, ClientKind.REMOTE_TCP));
  }

  @Test
  void aMapFolderLetsRemoteClientsLoadMapsAndRemoteExitIsItsOwnChoice() {
    CommandPolicy p = new CommandPolicy(Set.of(), false, true);
    assertNull(p.refusal(SIM_CTRL, 1, ClientKind.REMOTE_TCP));
    assertEquals(
        IgnoredCommand.Reason.REMOTE_CLIENT, p.refusal(SIM_EXIT, -1, ClientKind.REMOTE_TCP));
    assertNull(
        new CommandPolicy(Set.of(), true, false).refusal(SIM_EXIT, 0, ClientKind.REMOTE_TCP));
  }

  @Test
  void ignoredNumbersAreIgnoredForEveryone() {
    CommandPolicy p = new CommandPolicy(Set.of(SIM_EXIT, SIM_SET_POSE, SIM_CTRL), true, true);
    for (ClientKind k : ClientKind.values()) {
      assertEquals(IgnoredCommand.Reason.BY_OPTION, p.refusal(SIM_EXIT, -1, k));
      assertEquals(IgnoredCommand.Reason.BY_OPTION, p.refusal(SIM_SET_POSE, -1, k));
      assertEquals(IgnoredCommand.Reason.BY_OPTION, p.refusal(SIM_CTRL, 6, k));
      assertNull(p.refusal(VEL, -1, k));
    }
  }

  @Test
  void onlyLoopbackAddressesAreThisMachine() throws Exception {
    assertEquals(
        ClientKind.LOOPBACK_TCP,
        ClientKind.ofTcpPeer(
            new InetSocketAddress(InetAddress.getByAddress(new byte[] {127, 0, 0, 1}), 5000)));
    assertEquals(
        ClientKind.LOOPBACK_TCP,
        ClientKind.ofTcpPeer(
            new InetSocketAddress(
                InetAddress.getByAddress(
                    new byte[] {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1}),
                5000)));
    assertEquals(
        ClientKind.REMOTE_TCP,
        ClientKind.ofTcpPeer(
            new InetSocketAddress(
                InetAddress.getByAddress(new byte[] {(byte) 192, 0, 2, 7}), 5000)));
    assertEquals(
        ClientKind.REMOTE_TCP,
        ClientKind.ofTcpPeer(InetSocketAddress.createUnresolved("localhost", 5000)),
        "an address that is not known is not trusted");
  }
}
