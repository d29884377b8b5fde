package org.jaria.simvision;

import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.Trainer;
import org.jaria.acts.image.RgbImage;

/**
 * Trains a colour channel from a picture automatically, as a person would in EZ-Train: find the
 * pixels that clearly have the wanted hue, and "Add" the rectangle around them.
 */
public final class ColorTraining {

  private ColorTraining() {}

  /**
   * Trains {@code channel} of {@code bank} on the strongly red pixels of {@code image}.
   *
   * @return the number of red pixels found (0: nothing red in view, nothing trained)
   */
  public static int trainRed(ChannelBank bank, int channel, RgbImage image) {
    int minX = Integer.MAX_VALUE;
    int minY = Integer.MAX_VALUE;
    int maxX = -1;
    int maxY = -1;
    int count = 0;
    for (int y = 0; y < image.height(); y++) {
      for (int x = 0; x < image.width(); x++) {
        int p = image.get(x, y);
        int r = (p >> 16) & 0xFF;
        int g = (p >> 8) & 0xFF;
        int b = p & 0xFF;
        if (r > 90 && r > 2 * g && r > 2 * b) {
          count++;
          minX = Math.min(minX, x);
          maxX = Math.max(maxX, x);
          minY = Math.min(minY, y);
          maxY = Math.max(maxY, y);
        }
      }
    }
    if (count == 0) {
      return 0;
    }
    Trainer t = new Trainer(bank);
    t.setChannel(channel);
    // The inner half of the box: its edges mix in the background.
    int qx = (maxX - minX) / 4;
    int qy = (maxY - minY) / 4;
    t.addRect(image, minX + qx, minY + qy, maxX - qx, maxY - qy);
    return count;
  }
}
