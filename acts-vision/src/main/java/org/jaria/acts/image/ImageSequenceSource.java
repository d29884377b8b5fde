package org.jaria.acts.image;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * A source that plays a list of image files one frame each, in order (a recorded run, or a folder
 * of test pictures), scaling each to the working size; optionally starts again at the end.
 */
public final class ImageSequenceSource implements ImageSource {

  private final List<Path> files;
  private final int width;
  private final int height;
  private final boolean loop;
  private int next;

  /**
   * Plays {@code files} in the given order.
   *
   * @param loop whether to start again after the last file; if not, {@link #nextFrame} returns
   *     false at the end
   */
  public ImageSequenceSource(List<Path> files, int width, int height, boolean loop) {
    if (files.isEmpty()) {
      throw new IllegalArgumentException("an image sequence needs at least one file");
    }
    RgbImage.checkSize(width, height);
    this.files = List.copyOf(files);
    this.width = width;
    this.height = height;
    this.loop = loop;
  }

  /**
   * Plays every image file (.ppm, .pnm, .png, .jpg, .jpeg, .bmp, .gif) of a folder in name order.
   *
   * @throws IOException if the folder cannot be read or holds no image files
   */
  public static ImageSequenceSource ofDirectory(Path dir, int width, int height, boolean loop)
      throws IOException {
    if (!Files.isDirectory(dir)) {
      throw new NotDirectoryException(dir + " (expected a folder of image files)");
    }
    List<Path> found = new ArrayList<>();
    try (Stream<Path> s = Files.list(dir)) {
      s.filter(ImageSequenceSource::isImageFile).sorted().forEach(found::add);
    }
    if (found.isEmpty()) {
      throw new IOException(
          dir + " holds no image files (.ppm, .pnm, .png, .jpg, .jpeg, .bmp, .gif)");
    }
    return new ImageSequenceSource(found, width, height, loop);
  }

  /** Whether a file name has an image extension this source reads. */
  public static boolean isImageFile(Path p) {
    String n = p.getFileName().toString().toLowerCase(Locale.ROOT);
    return Files.isRegularFile(p)
        && (n.endsWith(".ppm")
            || n.endsWith(".pnm")
            || n.endsWith(".png")
            || n.endsWith(".jpg")
            || n.endsWith(".jpeg")
            || n.endsWith(".bmp")
            || n.endsWith(".gif"));
  }

  /** The files played, in order. */
  public List<Path> files() {
    return files;
  }

  @Override
  public int width() {
    return width;
  }

  @Override
  public int height() {
    return height;
  }

  @Override
  public boolean nextFrame(int[] rgb) throws IOException {
    if (next >= files.size()) {
      if (!loop) {
        return false;
      }
      next = 0;
    }
    RgbImage img = ImageFiles.read(files.get(next++)).scaled(width, height);
    System.arraycopy(img.pixels(), 0, rgb, 0, width * height);
    return true;
  }

  @Override
  public String describe() {
    return "sequence of "
        + files.size()
        + " images from "
        + files.get(0).toAbsolutePath().getParent()
        + " "
        + width
        + "x"
        + height
        + (loop ? " (looping)" : "");
  }
}
