package org.jaria.classroom.grading;

/** What happened to one submission, each with a sentence a student understands. */
public enum Status {
  /** Compiled, ran and was graded (the grade says how well it did). */
  GRADED,
  /** The student's folder holds no Java file to grade (or is a link, which is not followed). */
  NO_SUBMISSION,
  /** The submission is larger than a submission may be (files, bytes); nothing was compiled. */
  TOO_LARGE,
  /** The Java files do not compile. */
  COMPILE_ERROR,
  /** Compiling took more time or memory than allowed (or the compiler gave up); it was stopped. */
  COMPILE_LIMIT,
  /** Still running at the time limit (real or processor time); it was stopped. */
  TIMEOUT,
  /** Its Java machine ran out of memory. */
  OUT_OF_MEMORY,
  /** It started more threads or processes than allowed. */
  TOO_MANY_THREADS,
  /** It wrote more files, or more data, into its scratch folder than allowed; it was stopped. */
  TOO_MANY_FILES,
  /** It called System.exit, which ended its Java machine before grading was done. */
  EXIT,
  /** Its Java machine ended in any other way before grading was done. */
  CRASH;

  /** The sentence for a student, in {@code lang} ("en" or "es"). */
  public String sentence(String lang) {
    boolean es = "es".equals(lang);
    return switch (this) {
      case GRADED ->
          es
              ? "Tu programa se ejecutó y se evaluó en el simulador."
              : "Your program ran and was graded on the simulator.";
      case NO_SUBMISSION ->
          es
              ? "No hay ningún archivo .java que evaluar en tu carpeta: entrega tus archivos .java"
                  + " (no enlaces a ellos)."
              : "There is no .java file to grade in your folder: hand in your .java files"
                  + " themselves (not links to them).";
      case TOO_LARGE ->
          es
              ? "Tu entrega es más grande de lo permitido y no se compiló: entrega solo tus"
                  + " propios archivos fuente."
              : "Your submission is larger than allowed and was not compiled: hand in only your"
                  + " own source files.";
      case COMPILE_LIMIT ->
          es
              ? "Compilar tu código necesitó más tiempo o memoria de lo permitido y se detuvo:"
                  + " simplifica las expresiones muy largas o las llamadas genéricas muy anidadas."
              : "Compiling your code took more time or memory than allowed and was stopped:"
                  + " simplify very long expressions or deeply nested generic calls.";
      case COMPILE_ERROR ->
          es
              ? "Tu código no compila: corrige los errores indicados y vuelve a entregarlo."
              : "Your code does not compile: fix the errors shown and hand it in again.";
      case TIMEOUT ->
          es
              ? "Tu programa seguía ejecutándose al acabar el tiempo y se detuvo: busca un bucle"
                  + " que nunca termina en un constructor o en fire(), o uno que no espera en el"
                  + " reloj del robot."
              : "Your program was still running when its time was up and was stopped: look for a"
                  + " loop that never ends in a constructor or in fire(), or one that does not"
                  + " wait on the robot's clock.";
      case OUT_OF_MEMORY ->
          es
              ? "Tu programa se quedó sin memoria: ¿guardas datos sin fin en una lista o creas"
                  + " objetos en un bucle que nunca termina?"
              : "Your program ran out of memory: does it keep adding to a list without end, or"
                  + " create objects in a loop that never ends?";
      case TOO_MANY_THREADS ->
          es
              ? "Tu programa creó más hilos o procesos de los permitidos: no hacen falta hilos"
                  + " propios, el robot ya ejecuta tu código en su ciclo."
              : "Your program started more threads or processes than allowed: you need no"
                  + " threads of your own, the robot already runs your code on its cycle.";
      case TOO_MANY_FILES ->
          es
              ? "Tu programa creó más archivos, o escribió más datos, de los permitidos y se"
                  + " detuvo: un programa del robot no necesita escribir archivos; si guardas datos,"
                  + " usa uno solo y pequeño."
              : "Your program created more files, or wrote more data, than allowed and was"
                  + " stopped: a robot program needs to write no files; if you log data, use a"
                  + " single small file.";
      case EXIT ->
          es
              ? "Tu programa llamó a System.exit, que termina todo el programa Java (robot"
                  + " incluido): vuelve de run() en su lugar."
              : "Your program called System.exit, which ends the whole Java program (robot"
                  + " included): return from run() instead.";
      case CRASH ->
          es
              ? "La máquina Java de tu programa terminó de forma anómala antes de acabar la"
                  + " evaluación; mira su salida abajo."
              : "Your program's Java machine ended abnormally before grading was done; see its"
                  + " output below.";
    };
  }
}
