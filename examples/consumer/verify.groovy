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

// The README's "Maven coordinates" are the ones this project builds with, at this build's version.
def readme = new File(repoRoot, 'README.md').text
int section = readme.indexOf('## Maven coordinates')
assert section >= 0 : 'README.md has no "Maven coordinates" section'
int open = readme.indexOf('```xml\n', section) + '```xml\n'.length()
int close = readme.indexOf('```', open)
def doc = new groovy.xml.XmlSlurper().parseText('<project>' + readme.substring(open, close) + '</project>')
def pom = new groovy.xml.XmlSlurper().parse(new File(basedir, 'pom.xml'))
def bom = doc.dependencyManagement.dependencies.dependency[0]
assert bom.groupId.text() == 'org.jaria' && bom.artifactId.text() == 'jaria-bom'
assert bom.version.text() == jariaVersion : "README shows jaria-bom ${bom.version} but the build is ${jariaVersion}"
assert bom.type.text() == 'pom' && bom.scope.text() == 'import'
assert pom.dependencyManagement.dependencies.dependency.any {
  it.artifactId.text() == 'jaria-bom' && it.scope.text() == 'import'
}
assert doc.dependencies.dependency.size() > 0
doc.dependencies.dependency.each { d ->
  assert pom.dependencies.dependency.any {
    it.groupId.text() == d.groupId.text() && it.artifactId.text() == d.artifactId.text() &&
        it.scope.text() == d.scope.text() && it.version.text().isEmpty()
  } : "README's dependency ${d.groupId}:${d.artifactId} is not what examples/consumer uses"
}
return true
