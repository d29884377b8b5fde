// Run by maven-invoker-plugin after the consumer's build (it is not part of the example project).
// A user's first test run prints the test results and nothing else: no SLF4J "No SLF4J providers
// were found" warning, no JAria log lines below WARN, no stack traces.
def log = new File(basedir, 'build.log').text
int start = log.indexOf('T E S T S')
int end = log.indexOf('Results:', start)
assert start >= 0 && end > start : 'the consumer ran no tests'
def allowed = ~/\[INFO\] (-+|Running org\.example\..*|Tests run: .*)?\s*/
def noise = log.substring(start, end).readLines().drop(1).findAll { !(it ==~ allowed) }
assert noise.isEmpty() : "the consumer's test run printed more than its results:\n" + noise.join('\n')
assert log.contains('Tests run: 1, Failures: 0, Errors: 0, Skipped: 0') : 'ForwardTest did not pass'
return true
