package org.jaria.acts.config;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jaria.acts.ActsFormatException;
import org.jaria.acts.ActsProtocol;

/**
 * ACTS's preferences file ({@code ACTS.pref}, thesis table 5.60): start-up options that the command
 * line can override. Same line syntax as the runtime configuration ({@link KeyValueLines}); every
 * keyword is optional and takes the default below when absent.
 *
 * <pre>
 * ImageFile ""          ; still image to load instead of a camera
 * ConfigFile ""         ; runtime configuration to load
 * MinBlobSize 5         ; minimum blob width and height ("minimum run length and width")
 * Width 160
 * Height 120
 * Port 5001
 * GrabberType opencv    ; ACTS: vfw, v4l, pxc...; JAria always uses OpenCV
 * GrabberDevice -1      ; camera index (-1 = first) or device path
 * FramesPerSecond 30
 * ShowGraphics true     ; JAria's server has no window; kept for EZ-Train
 * PalCamera false
 * PxcGrabber false
 * InvertedImage false   ; camera mounted upside down: rotate frames by 180 degrees
 * GrabberChannel 1      ; input of a multi-input grabber card
 * </pre>
 *
 * @param imageFile still image file, or empty
 * @param configFile runtime configuration file, or empty
 * @param minBlobSize minimum blob width and height
 * @param width image width
 * @param height image height
 * @param port server port
 * @param grabberType grabber driver name (informational)
 * @param grabberDevice camera index or path
 * @param framesPerSecond most frames processed per second
 * @param showGraphics whether a training window is shown (for EZ-Train)
 * @param palCamera PAL rather than NTSC video
 * @param pxcGrabber whether a PXC200 card is used (not supported, informational)
 * @param invertedImage whether frames are rotated by 180°
 * @param grabberChannel grabber input number
 */
public record ActsPreferences(
    String imageFile,
    String configFile,
    int minBlobSize,
    int width,
    int height,
    int port,
    String grabberType,
    String grabberDevice,
    int framesPerSecond,
    boolean showGraphics,
    boolean palCamera,
    boolean pxcGrabber,
    boolean invertedImage,
    int grabberChannel) {

  /** The defaults of thesis table 5.60 (with OpenCV as the grabber). */
  public static final ActsPreferences DEFAULT =
      new ActsPreferences(
          "",
          "",
          5,
          160,
          120,
          ActsProtocol.DEFAULT_PORT,
          "opencv",
          "-1",
          30,
          true,
          false,
          false,
          false,
          1);

  /** Checks the ranges; null strings become empty. */
  public ActsPreferences {
    imageFile = imageFile == null ? "" : imageFile;
    configFile = configFile == null ? "" : configFile;
    grabberType = grabberType == null ? "" : grabberType;
    grabberDevice = grabberDevice == null || grabberDevice.isBlank() ? "-1" : grabberDevice;
    int max = ActsProtocol.MAX_2_DIGITS;
    check("MinBlobSize", minBlobSize, 1, max);
    check("Width", width, 1, max);
    check("Height", height, 1, max);
    check("Port", port, 0, 65535);
    check("FramesPerSecond", framesPerSecond, 1, 1000);
    check("GrabberChannel", grabberChannel, 0, 64);
  }

  private static void check(String what, int v, int min, int max) {
    if (v < min || v > max) {
      throw new IllegalArgumentException(what + " must be " + min + ".." + max + ", got " + v);
    }
  }

  /** Reads a preferences file. */
  public static ActsPreferences read(Path file) throws IOException {
    return fromLines(KeyValueLines.read(file), file.toString());
  }

  /** Parses preferences text; {@code name} is used in messages. */
  public static ActsPreferences parse(String text, String name) throws ActsFormatException {
    return fromLines(KeyValueLines.parse(text, name), name);
  }

  private static ActsPreferences fromLines(List<KeyValueLines.Line> lines, String name)
      throws ActsFormatException {
    ActsPreferences d = DEFAULT;
    String imageFile = d.imageFile;
    String configFile = d.configFile;
    int minBlobSize = d.minBlobSize;
    int width = d.width;
    int height = d.height;
    int port = d.port;
    String grabberType = d.grabberType;
    String grabberDevice = d.grabberDevice;
    int fps = d.framesPerSecond;
    boolean showGraphics = d.showGraphics;
    boolean pal = d.palCamera;
    boolean pxc = d.pxcGrabber;
    boolean inverted = d.invertedImage;
    int grabberChannel = d.grabberChannel;
    int max = ActsProtocol.MAX_2_DIGITS;
    for (KeyValueLines.Line l : lines) {
      switch (l.lowerKey()) {
        case "imagefile" -> imageFile = KeyValueLines.stringValue(l, name);
        case "configfile" -> configFile = KeyValueLines.stringValue(l, name);
        case "minblobsize" -> minBlobSize = KeyValueLines.intValue(l, 1, max, name);
        case "width" -> width = KeyValueLines.intValue(l, 1, max, name);
        case "height" -> height = KeyValueLines.intValue(l, 1, max, name);
        case "port" -> port = KeyValueLines.intValue(l, 0, 65535, name);
        case "grabbertype" -> grabberType = KeyValueLines.stringValue(l, name);
        case "grabberdevice" -> grabberDevice = KeyValueLines.stringValue(l, name);
        case "framespersecond" -> fps = KeyValueLines.intValue(l, 1, 1000, name);
        case "showgraphics" -> showGraphics = KeyValueLines.boolValue(l, name);
        case "palcamera" -> pal = KeyValueLines.boolValue(l, name);
        case "pxcgrabber" -> pxc = KeyValueLines.boolValue(l, name);
        case "invertedimage" -> inverted = KeyValueLines.boolValue(l, name);
        case "grabberchannel" -> grabberChannel = KeyValueLines.intValue(l, 0, 64, name);
        default ->
            throw new ActsFormatException(
                name,
                l.number(),
                "unknown preference '"
                    + l.key()
                    + "' (known: ImageFile, ConfigFile, MinBlobSize, Width, Height, Port,"
                    + " GrabberType, GrabberDevice, FramesPerSecond, ShowGraphics, PalCamera,"
                    + " PxcGrabber, InvertedImage, GrabberChannel)");
      }
    }
    return new ActsPreferences(
        imageFile,
        configFile,
        minBlobSize,
        width,
        height,
        port,
        grabberType,
        grabberDevice,
        fps,
        showGraphics,
        pal,
        pxc,
        inverted,
        grabberChannel);
  }

  /** The preferences as file text. */
  public String format() {
    return "; JAria ACTS preferences (ACTS.pref)\n"
        + "ImageFile "
        + KeyValueLines.quote(imageFile)
        + "\nConfigFile "
        + KeyValueLines.quote(configFile)
        + "\nMinBlobSize "
        + minBlobSize
        + "\nWidth "
        + width
        + "\nHeight "
        + height
        + "\nPort "
        + port
        + "\nGrabberType "
        + KeyValueLines.quote(grabberType)
        + "\nGrabberDevice "
        + KeyValueLines.quote(grabberDevice)
        + "\nFramesPerSecond "
        + framesPerSecond
        + "\nShowGraphics "
        + showGraphics
        + "\nPalCamera "
        + palCamera
        + "\nPxcGrabber "
        + pxcGrabber
        + "\nInvertedImage "
        + invertedImage
        + "\nGrabberChannel "
        + grabberChannel
        + "\n";
  }

  /** Writes the preferences file. */
  public void write(Path file) throws IOException {
    Files.writeString(file, format(), StandardCharsets.UTF_8);
  }
}
