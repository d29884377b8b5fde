package org.jaria.classroom.sandbox;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * The user ids that students' JVMs run as when the grader is root: one per running JVM on the whole
 * machine, not one per grading slot.
 *
 * <p>The kernel's process limit ({@code prlimit --nproc}) counts every process and thread of a
 * user. Had two students' JVMs the same user, they would share one limit: a thread bomb in one
 * grading would leave an honest student of another grading running at the same time (a second
 * {@code jaria grade}, or a second test JVM) unable to start a thread, and graded as a crash. So
 * each running JVM gets a user of its own: a lease is a lock on a file named after the user id, in
 * a folder only root can write; the kernel lets the lock go when the grader ends, however it ends.
 */
public final class SandboxUsers {

  /** How many user ids there are to hand out: {@link Sandbox#BASE_UID} and the ones above it. */
  public static final int COUNT = 256;

  /** Where the grader's lock files are, unless a test says otherwise: only root can write there. */
  public static final Path DEFAULT_FOLDER = Path.of("/run/jaria-grader");

  private final Path folder;

  private SandboxUsers(Path folder) {
    this.folder = folder;
  }

  /**
   * The user ids handed out through lock files in {@code folder} (made if missing, root's only).
   */
  public static SandboxUsers in(Path folder) {
    return new SandboxUsers(folder);
  }

  /**
   * The user ids of this machine's graders: lock files in {@link #DEFAULT_FOLDER}, or where {@code
   * /run} cannot be written (some containers), in the system's temporary folder.
   */
  public static SandboxUsers ofThisMachine() {
    boolean run = Files.isDirectory(DEFAULT_FOLDER) || Files.isWritable(DEFAULT_FOLDER.getParent());
    return new SandboxUsers(
        run ? DEFAULT_FOLDER : Path.of(System.getProperty("java.io.tmpdir"), "jaria-grader-users"));
  }

  /** One user id, held until the lease is closed. */
  public static final class Lease implements AutoCloseable {
    private final int uid;
    private final FileChannel channel;

    private Lease(int uid, FileChannel channel) {
      this.uid = uid;
      this.channel = channel;
    }

    /** No user of its own: the JVM runs as the grader's user, or in a user namespace. */
    static Lease none() {
      return new Lease(-1, null);
    }

    /** The user id the student's JVM runs as, or -1 if it gets none of its own. */
    public int uid() {
      return uid;
    }

    /** Gives the user id back. */
    @Override
    public void close() throws IOException {
      if (channel != null) {
        channel.close();
      }
    }
  }

  /**
   * A user id that no other JVM on this machine runs as until the lease is closed, trying first the
   * one of grading slot {@code slot}, so that a grading alone on the machine keeps the user ids it
   * always had.
   *
   * @throws IOException if the lock folder cannot be used, or all {@link #COUNT} users are busy
   */
  public Lease lease(int slot) throws IOException {
    prepareFolder();
    for (int i = 0; i < COUNT; i++) {
      int uid = Sandbox.BASE_UID + Math.floorMod(slot + i, COUNT);
      FileChannel ch =
          FileChannel.open(
              folder.resolve(uid + ".lock"),
              StandardOpenOption.CREATE,
              StandardOpenOption.WRITE,
              LinkOption.NOFOLLOW_LINKS);
      FileLock lock = null;
      try {
        lock = ch.tryLock();
      } catch (OverlappingFileLockException e) {
        // This JVM holds it already, for another of its students.
      } finally {
        if (lock == null) {
          ch.close();
        }
      }
      if (lock != null) {
        return new Lease(uid, ch);
      }
    }
    throw new IOException(
        "all "
            + COUNT
            + " users for students' JVMs ("
            + Sandbox.BASE_UID
            + " and up) are busy on this machine: wait for other gradings to end, or grade with"
            + " fewer --jobs");
  }

  private void prepareFolder() throws IOException {
    if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
      try {
        Files.createDirectory(
            folder,
            PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
      } catch (java.nio.file.FileAlreadyExistsException e) {
        // Made meanwhile by another grader: checked below.
      }
    }
    if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
      throw new IOException(
          folder + " is not a folder: remove it, so that the grader can keep its lock files there");
    }
    // In a shared temporary folder someone else could have made it first, to hold every lock.
    Object owner = Files.getAttribute(folder, "unix:uid", LinkOption.NOFOLLOW_LINKS);
    if (!owner.equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid"))) {
      throw new IOException(
          folder
              + " belongs to another user (uid "
              + owner
              + "): remove it, so that the grader can keep its lock files there");
    }
  }
}
