package org.jaria.classroom.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * How a student's JVM is started: inside a bubblewrap sandbox, or (only when the teacher says
 * {@code --unsafe}) as a plain process.
 *
 * <p>In the sandbox the JVM sees a read-only system library folder and JDK, JAria's own classes
 * read-only, and its scratch folder (a copy of its submission and its compiled classes) at {@code
 * /sandbox}, the only place it can write. It has its own process, network (no interface but an
 * unused loopback), IPC and host-name namespaces, so it can reach nothing over the network, sees no
 * other process, and every process it starts dies with it. Its only link to the grader is its
 * standard input and output. When the grader runs as root the JVM runs as an unprivileged user of
 * its own (from {@code 64000} up, one per running JVM on the machine: {@link SandboxUsers}),
 * because the kernel does not apply the process limit to root.
 */
public final class Sandbox {

  /** The lowest user id the sandboxed JVMs run as when the grader is root (see {@link #user}). */
  public static final int BASE_UID = 64000;

  /** Where bubblewrap is looked for unless the teacher says otherwise ({@code --bwrap}). */
  public static final Path DEFAULT_BWRAP = Path.of("/usr/bin/bwrap");

  private static final Path SETPRIV = Path.of("/usr/bin/setpriv");
  private static final Path PRLIMIT = Path.of("/usr/bin/prlimit");

  private final boolean isolated;
  private final boolean root;
  private final Path bwrap;
  private final SandboxUsers users = SandboxUsers.ofThisMachine();

  private Sandbox(boolean isolated, boolean root, Path bwrap) {
    this.isolated = isolated;
    this.root = root;
    this.bwrap = bwrap;
  }

  /**
   * The sandbox this machine offers.
   *
   * @throws IllegalStateException saying what to install or allow, if there is none
   */
  public static Sandbox bubblewrap() {
    return bubblewrap(DEFAULT_BWRAP);
  }

  /**
   * The sandbox made with the bubblewrap program at {@code bwrap}.
   *
   * @throws IllegalStateException saying what to install or allow, if it cannot isolate
   */
  public static Sandbox bubblewrap(Path bwrap) {
    Optional<String> why = whyUnavailable(bwrap);
    if (why.isPresent()) {
      throw new IllegalStateException(why.get());
    }
    return new Sandbox(true, isRoot(), bwrap);
  }

  /** A sandbox as it would be with or without root (for tests of the command it builds). */
  static Sandbox of(boolean isolated, boolean root) {
    return new Sandbox(isolated, root, DEFAULT_BWRAP);
  }

  /** No isolation at all: the student's JVM runs as the grader's user, with only its JVM limits. */
  public static Sandbox none() {
    return new Sandbox(false, false, DEFAULT_BWRAP);
  }

  /** Whether student JVMs are contained. */
  public boolean isolated() {
    return isolated;
  }

  /** Why bubblewrap cannot be used here, or empty if it can. */
  public static Optional<String> whyUnavailable() {
    return whyUnavailable(DEFAULT_BWRAP);
  }

  /** Why the bubblewrap program at {@code bwrap} cannot be used here, or empty if it can. */
  public static Optional<String> whyUnavailable(Path bwrap) {
    if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")) {
      return Optional.of(
          "isolating submissions needs Linux with bubblewrap; on this system grade only with"
              + " --unsafe, on code you trust");
    }
    for (Path p : List.of(bwrap, PRLIMIT)) {
      if (!Files.isExecutable(p)) {
        return Optional.of(
            p
                + " is missing: install bubblewrap and util-linux (apt-get install bubblewrap"
                + " util-linux) to grade in isolation");
      }
    }
    if (isRoot() && !Files.isExecutable(SETPRIV)) {
      return Optional.of(SETPRIV + " is missing: install util-linux (apt-get install util-linux)");
    }
    try {
      Process p =
          new ProcessBuilder(
                  bwrap.toString(),
                  "--ro-bind",
                  "/",
                  "/",
                  "--unshare-pid",
                  "--unshare-net",
                  "--die-with-parent",
                  "/bin/true")
              .redirectErrorStream(true)
              .start();
      boolean done = p.waitFor(20, TimeUnit.SECONDS);
      String out =
          new String(p.getInputStream().readNBytes(2000), java.nio.charset.StandardCharsets.UTF_8);
      if (!done || p.exitValue() != 0) {
        p.destroyForcibly();
        return Optional.of(
            "bubblewrap cannot make namespaces here ("
                + out.strip()
                + "); allow unprivileged user namespaces (sysctl kernel.unprivileged_userns_clone=1)"
                + " or run the grader as root in a machine of its own");
      }
    } catch (IOException e) {
      return Optional.of("bubblewrap does not start: " + e.getMessage());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      return Optional.of("interrupted while trying bubblewrap");
    }
    return Optional.empty();
  }

  private static boolean isRoot() {
    try {
      Object uid = Files.getAttribute(Path.of("/proc/self"), "unix:uid");
      return Integer.valueOf(0).equals(uid);
    } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
      return "root".equals(System.getProperty("user.name"));
    }
  }

  /**
   * The user that the JVM of grading slot {@code slot} runs as, held until the lease is closed:
   * when the grader is root, a user no other student's JVM on this machine has meanwhile (see
   * {@link SandboxUsers}); otherwise none ({@code uid()} -1).
   *
   * @throws IOException if no user can be had (all busy, or the lock folder unusable)
   */
  public SandboxUsers.Lease user(int slot) throws IOException {
    return isolated && root ? users.lease(slot) : SandboxUsers.Lease.none();
  }

  /**
   * Gives the scratch folder to the sandbox's user {@code uid} (from {@link #user}; -1: none), so
   * the student's JVM can write there and nowhere else.
   */
  public void prepare(Path scratch, int uid) throws IOException {
    if (uid < 0) {
      return;
    }
    try (var s = Files.walk(scratch)) {
      for (Path p : s.toList()) {
        Files.setAttribute(p, "unix:uid", uid, java.nio.file.LinkOption.NOFOLLOW_LINKS);
        Files.setAttribute(p, "unix:gid", uid, java.nio.file.LinkOption.NOFOLLOW_LINKS);
      }
    }
  }

  /**
   * The command that runs {@code mainClass} with {@code args} in a student's JVM.
   *
   * @param scratch the student's scratch folder (seen as /sandbox inside)
   * @param classPath JAria's class path entries (bound read-only at their own paths)
   * @param limits the limits
   * @param uid the user it runs as (from {@link #user}; -1 when the grader is not root)
   * @param mainClass the JVM's main class
   * @param args its arguments; a path inside scratch is given as under /sandbox
   */
  public List<String> command(
      Path scratch,
      List<Path> classPath,
      Limits limits,
      int uid,
      String mainClass,
      List<String> args) {
    Path javaHome = realJavaHome();
    String javaBin = javaHome.resolve("bin").resolve("java").toString();
    List<String> jvm = new ArrayList<>();
    jvm.add(javaBin);
    jvm.addAll(limits.jvmOptions());
    List<String> cmd = new ArrayList<>();
    if (!isolated) {
      jvm.add("-Djava.io.tmpdir=" + scratch.resolve("tmp"));
      jvm.add("-cp");
      jvm.add(
          String.join(java.io.File.pathSeparator, classPath.stream().map(Path::toString).toList()));
      jvm.add(mainClass);
      for (String a : args) {
        jvm.add(a.startsWith("/sandbox") ? scratch + a.substring("/sandbox".length()) : a);
      }
      return jvm;
    }
    cmd.add(PRLIMIT.toString());
    if (root) {
      cmd.add("--nproc=" + limits.tasks());
    }
    cmd.add("--cpu=" + Math.max(1, limits.cpu().toSeconds()));
    cmd.add("--fsize=" + limits.fileBytes());
    cmd.add("--core=0");
    cmd.add("--");
    cmd.addAll(
        List.of(
            bwrap.toString(),
            "--die-with-parent",
            "--new-session",
            "--unshare-pid",
            "--unshare-net",
            "--unshare-ipc",
            "--unshare-uts",
            "--unshare-cgroup-try",
            "--hostname",
            "sandbox"));
    if (!root) {
      cmd.addAll(List.of("--unshare-user", "--uid", "65534", "--gid", "65534"));
    }
    cmd.addAll(List.of("--perms", "0755", "--dir", "/usr", "--perms", "0755", "--dir", "/etc"));
    cmd.addAll(List.of("--ro-bind", "/usr/lib", "/usr/lib", "--symlink", "usr/lib", "/lib"));
    if (Files.isDirectory(Path.of("/usr/lib64"))) {
      cmd.addAll(
          List.of("--ro-bind", "/usr/lib64", "/usr/lib64", "--symlink", "usr/lib64", "/lib64"));
    }
    bind(cmd, javaHome);
    // Debian's JDK keeps its configuration under /etc, linked from files in JAVA_HOME/conf.
    for (Path target : linkedFolders(javaHome.resolve("conf"), javaHome)) {
      bind(cmd, target);
    }
    if (root) {
      bind(cmd, SETPRIV);
    }
    for (Path p : classPath) {
      bind(cmd, p);
    }
    cmd.addAll(
        List.of(
            "--bind",
            scratch.toString(),
            "/sandbox",
            "--dev",
            "/dev",
            "--proc",
            "/proc",
            "--chdir",
            "/sandbox",
            "--clearenv",
            "--setenv",
            "HOME",
            "/sandbox",
            "--setenv",
            "LANG",
            "C.UTF-8",
            "--"));
    if (root) {
      if (uid < 0) {
        throw new IllegalArgumentException(
            "a student's JVM started by root needs a user of its own: lease one with user(slot)");
      }
      cmd.addAll(
          List.of(
              SETPRIV.toString(),
              "--reuid=" + uid,
              "--regid=" + uid,
              "--clear-groups",
              "--inh-caps=-all",
              "--bounding-set=-all",
              "--no-new-privs"));
    }
    cmd.addAll(jvm);
    cmd.add("-Djava.io.tmpdir=/sandbox/tmp");
    cmd.add("-cp");
    cmd.add(
        String.join(java.io.File.pathSeparator, classPath.stream().map(Path::toString).toList()));
    cmd.add(mainClass);
    cmd.addAll(args);
    return cmd;
  }

  private static void bind(List<String> cmd, Path p) {
    String s = p.toString();
    if (s.startsWith("/usr/lib/") || s.startsWith("/usr/lib64/")) {
      return; // already visible
    }
    // bubblewrap makes missing parent folders readable by their owner only: make them traversable
    Path parent = p.getParent();
    List<String> dirs = new ArrayList<>();
    for (Path q = parent; q != null && q.getNameCount() > 0; q = q.getParent()) {
      dirs.add(0, q.toString());
    }
    for (String d : dirs) {
      if (!d.equals("/usr") && !d.equals("/etc") && !d.startsWith("/usr/lib")) {
        cmd.addAll(List.of("--perms", "0755", "--dir", d));
      }
    }
    cmd.addAll(List.of("--ro-bind", s, s));
  }

  /**
   * The top folders (two levels, e.g. /etc/java-17-openjdk) that links under {@code dir} point
   * into, outside {@code home}.
   */
  private static java.util.Set<Path> linkedFolders(Path dir, Path home) {
    java.util.Set<Path> out = new java.util.TreeSet<>();
    if (!Files.isDirectory(dir)) {
      return out;
    }
    try (var s = Files.walk(dir)) {
      for (Path p : s.filter(Files::isSymbolicLink).toList()) {
        try {
          Path real = p.toRealPath();
          if (!real.startsWith(home) && real.getNameCount() >= 2) {
            out.add(real.getRoot().resolve(real.subpath(0, 2)));
          }
        } catch (IOException e) {
          // a dangling link: nothing to bind
        }
      }
    } catch (IOException e) {
      // unreadable: the JVM will say what it misses
    }
    return out;
  }

  private static Path realJavaHome() {
    Path home = Path.of(System.getProperty("java.home"));
    try {
      return home.toRealPath();
    } catch (IOException e) {
      return home;
    }
  }
}
