package org.jaria.net.data;

/**
 * One entry of a server's data list, sent at login (ArNetworking's LIST, LISTARGRET and
 * LISTGROUPANDFLAGS packets): what a client may ask for and how.
 *
 * @param id the command number used on the wire (256 and up, given in registration order)
 * @param name the name clients use ("update", "getMap", "ratioDrive" ...)
 * @param description what it is
 * @param argumentDescription the arguments, in order ("none" if none)
 * @param returnDescription the reply, in order ("none" if none)
 * @param commandGroup the group a user needs ("" for anybody)
 * @param dataFlags ArNetworking's data flags joined by '|' ("RETURN_SINGLE", "RETURN_NONE" ...)
 */
public record DataInfo(
    int id,
    String name,
    String description,
    String argumentDescription,
    String returnDescription,
    String commandGroup,
    String dataFlags) {

  /** Whether the flags contain {@code flag}. */
  public boolean hasDataFlag(String flag) {
    return ("|" + dataFlags + "|").contains("|" + flag + "|");
  }

  /**
   * Whether a request gets no reply: the flags say RETURN_NONE, or (a server that sends no flags)
   * the return description is "none".
   */
  public boolean returnsNothing() {
    if (hasDataFlag("RETURN_NONE")) {
      return true;
    }
    if (hasDataFlag("RETURN_SINGLE")
        || hasDataFlag("RETURN_VIDEO")
        || hasDataFlag("RETURN_UNTIL_EMPTY")
        || hasDataFlag("RETURN_COMPLEX")) {
      return false;
    }
    return returnDescription.isBlank() || returnDescription.equalsIgnoreCase("none");
  }

  /** A copy with another argument and return description. */
  public DataInfo withArgRet(String arg, String ret) {
    return new DataInfo(id, name, description, arg, ret, commandGroup, dataFlags);
  }

  /** A copy with another command group and flags. */
  public DataInfo withGroupAndFlags(String group, String flags) {
    return new DataInfo(
        id, name, description, argumentDescription, returnDescription, group, flags);
  }
}
