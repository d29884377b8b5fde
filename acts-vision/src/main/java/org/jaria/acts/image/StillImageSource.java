package org.jaria.acts.image;

import java.io.IOException;
import java.nio.file.Path;

/**
 * A source that returns the same picture for every frame (ACTS's {@code -f test.ppm} and EZ-Train's
 * Load Image). The picture is scaled to the working size once, when the source is made.
 */
public final class StillImageSource implements ImageSource {

  private final RgbImage image;
  private final String name;

  /** A source showing {@code image} scaled to {@code width × height}. */
  public StillImageSource(RgbImage image, int width, int height, String name) {
    this.image = image.scaled(width, height).copy();
    this.name = name;
  }

  /** A source showing {@code image} at its own size. */
  public StillImageSource(RgbImage image) {
    this(image, image.width(), image.height(), "image");
  }

  /** Loads an image file (PPM, PNG, JPEG, ...) and scales it to {@code width × height}. */
  public static StillImageSource open(Path file, int width, int height) throws IOException {
    return new StillImageSource(ImageFiles.read(file), width, height, file.toString());
  }

  /** The (scaled) picture. */
  public RgbImage image() {
    return image.copy();
  }

  @Override
  public int width() {
    return image.width();
  }

  @Override
  public int height() {
    return image.height();
  }

  @Override
  public boolean nextFrame(int[] rgb) {
    System.arraycopy(image.pixels(), 0, rgb, 0, image.pixels().length);
    return true;
  }

  @Override
  public String describe() {
    return "image " + name + " " + width() + "x" + height();
  }
}
